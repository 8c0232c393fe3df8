#pragma once
// Reflection geometry shared by every stage. A plane is n . x + d = 0 with |n| = 1
// (SymmetryPlane in segmentation_result.h).

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

inline float signedDistance(const SymmetryPlane& plane, const Eigen::Vector3f& point) {
  return plane.normal.dot(point) + plane.distance;
}

inline Eigen::Vector3f reflectPoint(const SymmetryPlane& plane, const Eigen::Vector3f& point) {
  return point - 2.0f * signedDistance(plane, point) * plane.normal;
}

inline Eigen::Vector3f reflectDirection(const SymmetryPlane& plane, const Eigen::Vector3f& direction) {
  return direction - 2.0f * direction.dot(plane.normal) * plane.normal;
}

/// The plane that reflects `a` onto `b` (perpendicular bisector). Requires a != b.
inline SymmetryPlane bisectorPlane(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  SymmetryPlane plane;
  plane.normal = (b - a).normalized();
  plane.distance = -plane.normal.dot(0.5f * (a + b));
  return plane;
}

/// n and -n describe the same plane: pick the sign with the first non-negligible component
/// positive (x, then y, then z), so equal planes have equal coefficients.
inline SymmetryPlane canonicalPlane(SymmetryPlane plane) {
  const Eigen::Vector3f& n = plane.normal;
  const float lead = std::fabs(n.x()) > 1e-6f ? n.x() : (std::fabs(n.y()) > 1e-6f ? n.y() : n.z());
  if (lead < 0.0f) {
    plane.normal = -plane.normal;
    plane.distance = -plane.distance;
  }
  return plane;
}

/// The vertical plane (for the unit normal `up` of the table) through `point` whose normal is
/// `direction` made horizontal, with the canonical sign. Requires `direction` not parallel to `up`.
inline SymmetryPlane verticalPlaneThrough(const Eigen::Vector3f& point, Eigen::Vector3f direction,
                                          const Eigen::Vector3f& up) {
  direction -= direction.dot(up) * up;
  SymmetryPlane plane;
  plane.normal = direction.normalized();
  plane.distance = -plane.normal.dot(point);
  return canonicalPlane(plane);
}

/// Angle between two planes' normals in degrees, ignoring orientation (0..90).
inline float planeAngleDeg(const SymmetryPlane& a, const SymmetryPlane& b) {
  const float c = std::min(1.0f, std::fabs(a.normal.dot(b.normal)));
  return std::acos(c) * 180.0f / static_cast<float>(M_PI);
}

/// Offset difference of two planes after aligning their orientation (m).
inline float planeDistanceDifference(const SymmetryPlane& a, const SymmetryPlane& b) {
  return a.normal.dot(b.normal) >= 0.0f ? std::fabs(a.distance - b.distance) : std::fabs(a.distance + b.distance);
}

}  // namespace symmetry_segmentation
