#pragma once
// A rigid synthetic object: a union of surface patches in its local frame (z up, base on z = 0,
// mirror-symmetric about the local plane y = 0), placed in the world by a pose.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "symmetry_segmentation/synthetic/footprint.h"
#include "symmetry_segmentation/synthetic/surface_patch.h"

namespace symmetry_segmentation {
namespace synthetic {

enum class ObjectShape { Table, Box, Cylinder, Bottle, Bowl, Mug, Cone, LShape, UShape, Ball, Pot, Book };

std::string toString(ObjectShape shape);

using Rgb = std::array<uint8_t, 3>;

/// A printed surface (packaging, labels): rectangular blocks of a few inks over the base
/// colour, fixed to the object so every view sees the same print. Real objects are rarely one
/// flat colour, and a segmenter that cuts at colour changes must not cut them apart.
struct Print {
  bool enabled = false;
  double block = 0.03;          ///< Edge of the print's blocks (m), local frame.
  double ink_share = 0.5;       ///< Fraction of blocks in an ink rather than the base colour.
  std::array<Rgb, 3> inks{};
  uint64_t seed = 0;            ///< Which blocks get which ink.
};

struct SyntheticObject {
  ObjectShape shape = ObjectShape::Box;
  std::vector<SurfacePatch> patches;  ///< Local frame; the first hit along a ray wins.
  Eigen::Vector3d local_min = Eigen::Vector3d::Zero();  ///< Bounds of all patches (local).
  Eigen::Vector3d local_max = Eigen::Vector3d::Zero();
  Footprint footprint;  ///< Convex outline on the table in the local frame.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< Local to world.
  int label = 0;         ///< 0 = table / background, 1..N objects.
  Rgb color{{128, 128, 128}};
  Print print;

  double height() const { return local_max.z(); }
  /// Base position (z of the local origin) and heading in the world.
  Eigen::Vector3d position() const { return pose.translation(); }
  /// Footprint in world coordinates (ignores any tilt: objects only yaw).
  Footprint worldFootprint() const;
  /// Top of the object in world z.
  double worldTop() const { return pose.translation().z() + local_max.z(); }
};

/// Adds a patch and grows the bounds and footprint.
void addPatch(SyntheticObject& object, const SurfacePatch& patch);

/// Pose for an object standing upright at (x, y, z) turned by yaw about the vertical.
Eigen::Isometry3d uprightPose(double x, double y, double z, double yaw);

/// Colour of the object's surface at a world point on it: the base colour or the print's ink.
Rgb surfaceColor(const SyntheticObject& object, const Eigen::Vector3d& world_point);

struct ObjectHit {
  double t = 0.0;
  Eigen::Vector3d point;   ///< World frame.
  Eigen::Vector3d normal;  ///< World frame, unit, out of the material.
};

/// First hit of a world-frame ray on the object with t in [t_min, t_max].
std::optional<ObjectHit> rayIntersect(const SyntheticObject& object, const Ray& world_ray, double t_min,
                                      double t_max);

}  // namespace synthetic
}  // namespace symmetry_segmentation
