#pragma once
// The shape of each merged surface as PCA sees it, computed once for the stages that propose
// planes from single surfaces (upright: vertical planes and planes halfway up).

#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

/// One merged surface: its points and their principal shape.
struct SurfaceShape {
  std::vector<int> points;  ///< Ascending.
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  Eigen::Vector3f mean_normal = Eigen::Vector3f::Zero();  ///< Mean of the unit normals (shorter when they spread).
  Eigen::Matrix3f scatter = Eigen::Matrix3f::Zero();      ///< Sum of outer products of the offsets from the centroid.
  float curvature = 0.0f;  ///< Smallest eigenvalue of the scatter over their sum: 0 for a plane.
  Eigen::Vector3f face_normal = Eigen::Vector3f::UnitZ();  ///< The scatter's least direction.
};

/// The surfaces of `cloud` by label (from mergedSegmentLabels; 0 = none), one per label in use,
/// ordered by label. `labels` has one entry per point, else none.
std::vector<SurfaceShape> surfaceShapes(const Cloud& cloud, const std::vector<int>& labels);

}  // namespace symmetry_segmentation
