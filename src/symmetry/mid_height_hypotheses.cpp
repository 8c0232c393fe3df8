// Horizontal planes halfway up objects (see the header for why).
#include "symmetry_segmentation/symmetry/mid_height_hypotheses.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {
namespace {

constexpr float kDegToRad = static_cast<float>(M_PI) / 180.0f;

struct HorizontalFace {
  std::vector<int> points;
  float height = 0.0f;        ///< Median height over the table's plane.
  float table_height = 0.0f;  ///< The table top's height over its plane under the face's centroid.
  Eigen::AlignedBox2f extent;  ///< In the table plane's coordinates.
};

float median(std::vector<float> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

std::vector<SymmetryHypothesis> midHeightHypotheses(const Cloud& cloud, const std::vector<int>& labels,
                                                    const TableTop& table, const UprightHypothesisParams& params,
                                                    float reach) {
  std::vector<SymmetryHypothesis> result;
  const float norm = table.plane.head<3>().norm();
  if (!(params.min_mid_height > 0.0f) || !(norm > 0.0f) || labels.size() != cloud.size()) return result;
  const Eigen::Vector3f up = table.plane.head<3>() / norm;
  const float offset = table.plane[3] / norm;
  const Eigen::Vector3f e1 = up.unitOrthogonal();
  const Eigen::Vector3f e2 = up.cross(e1);
  const float horizontal_cos = std::cos(params.face_tilt_deg * kDegToRad);

  int max_label = 0;
  for (int label : labels) max_label = std::max(max_label, label);
  std::vector<std::vector<int>> surfaces(max_label + 1);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] > 0) surfaces[labels[i]].push_back(static_cast<int>(i));
  }
  std::vector<HorizontalFace> faces;
  for (std::vector<int>& points : surfaces) {
    const int n = static_cast<int>(points.size());
    if (n < params.min_surface_points) continue;
    Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
    for (int i : points) centroid += cloud.points[i].getVector3fMap();
    centroid /= static_cast<float>(n);
    Eigen::Matrix3f covariance = Eigen::Matrix3f::Zero();
    for (int i : points) {
      const Eigen::Vector3f d = cloud.points[i].getVector3fMap() - centroid;
      covariance += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> pca(covariance);
    const float curvature = pca.eigenvalues()(0) / std::max(1e-12f, pca.eigenvalues().sum());
    if (!(curvature < params.flat_curvature) || !(std::fabs(pca.eigenvectors().col(0).dot(up)) > horizontal_cos)) {
      continue;
    }
    HorizontalFace face;
    std::vector<float> heights;
    heights.reserve(points.size());
    for (int i : points) {
      const Eigen::Vector3f p = cloud.points[i].getVector3fMap();
      heights.push_back(up.dot(p) + offset);
      face.extent.extend(Eigen::Vector2f(e1.dot(p), e2.dot(p)));
    }
    face.height = median(std::move(heights));
    face.table_height = up.dot(centroid) + offset - table.height(centroid);
    face.points = std::move(points);
    faces.push_back(std::move(face));
  }

  const auto horizontalPlane = [&](float height, const HorizontalFace& face) {
    SymmetryHypothesis h;
    h.plane.normal = up;
    h.plane.distance = offset - height;
    h.plane = canonicalPlane(h.plane);
    h.support = static_cast<int>(face.points.size());
    h.anchor = face.points;
    return h;
  };
  for (const HorizontalFace& face : faces) {
    if (face.height - face.table_height < params.min_mid_height) continue;
    result.push_back(horizontalPlane(0.5f * (face.height + face.table_height), face));
    Eigen::AlignedBox2f near = face.extent;
    near.min().array() -= reach;
    near.max().array() += reach;
    for (const HorizontalFace& lower : faces) {
      if (face.height - lower.height < params.min_mid_height || lower.height - lower.table_height < params.min_mid_height) {
        continue;
      }
      if (near.intersects(lower.extent)) result.push_back(horizontalPlane(0.5f * (face.height + lower.height), face));
    }
  }
  return result;
}

}  // namespace symmetry_segmentation
