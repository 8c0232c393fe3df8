// Per-surface PCA (see the header for why it is shared).
#include "symmetry_segmentation/symmetry/surface_shapes.h"

#include <algorithm>

#include <Eigen/Eigenvalues>

namespace symmetry_segmentation {

std::vector<SurfaceShape> surfaceShapes(const Cloud& cloud, const std::vector<int>& labels) {
  if (labels.size() != cloud.size()) return {};
  int max_label = 0;
  for (int label : labels) max_label = std::max(max_label, label);
  std::vector<std::vector<int>> members(max_label + 1);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] > 0) members[labels[i]].push_back(static_cast<int>(i));
  }
  std::vector<SurfaceShape> shapes;
  for (std::vector<int>& points : members) {
    if (points.empty()) continue;
    SurfaceShape shape;
    const float n = static_cast<float>(points.size());
    for (int i : points) {
      shape.centroid += cloud.points[i].getVector3fMap();
      shape.mean_normal += cloud.points[i].getNormalVector3fMap();
    }
    shape.centroid /= n;
    shape.mean_normal /= n;
    for (int i : points) {
      const Eigen::Vector3f d = cloud.points[i].getVector3fMap() - shape.centroid;
      shape.scatter += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> pca(shape.scatter);  // Ascending eigenvalues.
    shape.curvature = pca.eigenvalues()(0) / std::max(1e-12f, pca.eigenvalues().sum());
    shape.face_normal = pca.eigenvectors().col(0);
    shape.points = std::move(points);
    shapes.push_back(std::move(shape));
  }
  return shapes;
}

}  // namespace symmetry_segmentation
