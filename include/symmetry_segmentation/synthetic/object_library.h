#pragma once
// Builders for the bilaterally symmetric household objects of the synthetic scenes, in their
// local frame (z up, base on z = 0, mirror plane y = 0). Dimensions in metres.

#include <vector>

#include "symmetry_segmentation/synthetic/random.h"
#include "symmetry_segmentation/synthetic/synthetic_object.h"

namespace symmetry_segmentation {
namespace synthetic {

SyntheticObject makeBox(double size_x, double size_y, double size_z);
SyntheticObject makeCylinder(double radius, double height);
SyntheticObject makeCone(double radius, double height);

struct BottleSize {
  double body_radius = 0.035;
  double body_height = 0.14;
  double shoulder_height = 0.04;
  double neck_radius = 0.014;
  double neck_height = 0.04;
};
SyntheticObject makeBottle(const BottleSize& size);

/// Spherical bowl: rim of `radius` at `height` (< radius), flat foot, walls `wall` thick.
SyntheticObject makeBowl(double radius, double height, double wall);

struct MugSize {
  double radius = 0.04;
  double height = 0.1;
  double wall = 0.005;
  double bottom = 0.008;
  double handle_reach = 0.03;      ///< How far the handle sticks out of the wall (+x).
  double handle_width = 0.016;     ///< Extent across the mirror plane (y).
  double handle_thickness = 0.01;  ///< Bar thickness.
};
/// Open cup with a handle built from three thin boxes in the mirror plane, on the +x side.
SyntheticObject makeMug(const MugSize& size);

/// Plate of length x width x thickness with an upright of `height` at the -x end.
SyntheticObject makeLShape(double length, double width, double thickness, double height);
/// Plate with uprights at both ends.
SyntheticObject makeUShape(double length, double width, double thickness, double height);

/// Ball of `radius` resting on the table.
SyntheticObject makeBall(double radius);
/// Closed tapered pot (flower pot, yoghurt tub): a frustum with a lid.
SyntheticObject makePot(double bottom_radius, double top_radius, double height);
/// A box lying flat (book, board): length x width, `thickness` high; shape Book.
SyntheticObject makeBook(double length, double width, double thickness);

/// Thick table top of size_x x size_y whose top face is z = 0 (label 0).
SyntheticObject makeTable(double size_x, double size_y, double thickness);

/// An object of `shape` with sizes drawn from realistic ranges (5-30 cm).
SyntheticObject makeRandomObject(ObjectShape shape, Random& random);
/// A random box in the given ranges.
SyntheticObject makeRandomBox(Random& random, double min_size, double max_size);

/// The shapes of the fixed generated set (not the table), for drawing mixed sets.
const std::vector<ObjectShape>& objectShapes();
/// objectShapes() plus the shapes the realistic scenes add (ball, pot); books are laid
/// separately, flat on the table.
const std::vector<ObjectShape>& moreObjectShapes();

/// A distinct, plausible colour for the object with this label.
Rgb colorForLabel(int label);

}  // namespace synthetic
}  // namespace symmetry_segmentation
