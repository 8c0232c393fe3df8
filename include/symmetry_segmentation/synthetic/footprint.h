#pragma once
// 2-D convex footprints on the table, used to lay objects out without interpenetration.

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace symmetry_segmentation {
namespace synthetic {

/// Convex polygon, counter-clockwise, in the table plane (x, y).
using Footprint = std::vector<Eigen::Vector2d>;

/// Convex hull (Andrew's monotone chain); collinear points are dropped.
Footprint convexHull(std::vector<Eigen::Vector2d> points);

/// Regular polygon circumscribing a circle, so the polygon never underestimates the shape.
std::vector<Eigen::Vector2d> circumscribedPolygon(double radius, int sides = 16);

/// `footprint` rotated by `yaw` and moved to `position`.
Footprint placeFootprint(const Footprint& footprint, const Eigen::Vector2d& position, double yaw);

/// Largest gap between two convex polygons along any of their edge normals (separating axis
/// test). Negative when they overlap; a positive value is a lower bound on their distance.
double separation(const Footprint& a, const Footprint& b);

/// Axis-aligned extent of a footprint.
void footprintBounds(const Footprint& footprint, Eigen::Vector2d& min, Eigen::Vector2d& max);

}  // namespace synthetic
}  // namespace symmetry_segmentation
