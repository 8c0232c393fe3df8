#pragma once
// Background surfaces: walls, shelf backs, the floor. A plane is mirror-symmetric about every
// plane across it, so symmetry never rules them out; and a wall a few centimetres behind the
// table's edge reaches into the table's polygon (grown by its margin) and comes out as a flat
// "object" the size of a box face. What tells it apart is that it goes on: a flat patch wider
// than any graspable object that also lies outside the tabletop region is not an object.

#include <vector>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

struct BackgroundSurfaceParams {
  float ransac_distance = 0.01f;  ///< On a plane: this close to it (m).
  int ransac_iterations = 500;
  float connect_distance = 0.045f;  ///< Points of one patch are this close to the next (m).
  float max_object_extent = 0.5f;   ///< A patch wider than this is no object's face (m).
};

/// Per point of `cloud` (a coarse copy of the scene): whether it lies on a background surface -
/// a connected patch of one plane, among the points marked `candidate`, that spans more than
/// `max_object_extent`, covers its extent like a surface (a plane slicing through objects meets
/// only thin rings of them) and has points both in and outside `in_region`.
std::vector<bool> backgroundSurfacePoints(const Cloud& cloud, const std::vector<bool>& candidate,
                                          const std::vector<bool>& in_region, const BackgroundSurfaceParams& params);

}  // namespace symmetry_segmentation
