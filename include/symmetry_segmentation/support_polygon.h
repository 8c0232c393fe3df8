#pragma once
// The extent of the supporting surface: the convex polygon of the table's own points, grown by a
// margin. Only what stands over it is a tabletop object; walls, the floor, other furniture and
// the far background of a single view lie outside it (a plane is mirror-symmetric about every
// plane across it, so symmetry alone never rules them out).

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

/// A surface seen this deep under the table's top (m) runs on below it: a table hides what is
/// under its top from a sensor over it, so what is seen there is a wall, a chair's back, a
/// table's edge. (Clear of the table's noise; one or two 1.5 cm voxels deep.)
constexpr float kSeenUnderTopMin = 0.03f;
constexpr float kSeenUnderTopMax = 0.06f;

class SupportPolygon {
 public:
  /// The polygon of the points of `cloud` within `on_plane_distance` of `plane` (the largest
  /// group of them connected within `connect_distance`: a coplanar shelf or second table apart
  /// stays out), grown by `margin`. `plane` faces up (the side things stand on). Points of the
  /// group with a surface seen 3-6 cm right under them (a wall or a chair's back crossing the
  /// plane; a table hides what is under it) give it no extent. None when fewer than three such
  /// points span an area.
  static std::optional<SupportPolygon> fromPlanePoints(const Cloud& cloud, const PlaneCoefficients& plane,
                                                       float on_plane_distance, float connect_distance, float margin);

  /// Whether `point` lies over (or under) the polygon, along the plane's normal.
  bool contains(const Eigen::Vector3f& point) const;

  /// Whether `point` lies over (or under) the table's own points' polygon: without the margin.
  bool overTable(const Eigen::Vector3f& point) const;

  /// The corners on the plane, in order around it (input frame).
  std::vector<Eigen::Vector3f> corners() const;

 private:
  Eigen::Vector2f inPlane(const Eigen::Vector3f& point) const;
  /// Whether `point` (in-plane) is inside the convex polygon `corners` (counter-clockwise).
  static bool inside(const std::vector<Eigen::Vector2f>& corners, const Eigen::Vector2f& point);

  Eigen::Vector3f origin_ = Eigen::Vector3f::Zero();  ///< On the plane.
  Eigen::Vector3f u_ = Eigen::Vector3f::UnitX(), v_ = Eigen::Vector3f::UnitY();  ///< In-plane axes.
  std::vector<Eigen::Vector2f> corners_;        ///< Counter-clockwise in (u, v).
  std::vector<Eigen::Vector2f> table_corners_;  ///< The same before the margin.
};

}  // namespace symmetry_segmentation
