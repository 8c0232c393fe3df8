#pragma once
// Which points the pipeline can use. Coordinates beyond 100 km are not tabletop data, and
// converting them to voxel keys (double -> int64) would overflow, so they count as unusable
// just like NaN or infinite ones.

#include <cmath>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

/// Largest |x|, |y| or |z| (m) a usable point may have.
constexpr float kMaxUsableCoordinate = 1e5f;

inline bool isUsableCoordinate(float value) {
  return std::isfinite(value) && std::fabs(value) <= kMaxUsableCoordinate;
}

/// Finite and within kMaxUsableCoordinate on every axis.
inline bool isUsablePoint(const PointT& point) {
  return isUsableCoordinate(point.x) && isUsableCoordinate(point.y) && isUsableCoordinate(point.z);
}

}  // namespace symmetry_segmentation
