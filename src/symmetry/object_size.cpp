// Stage 17, object_size: only what a robot could grasp is an object (see the header).
#include "symmetry_segmentation/symmetry/object_size.h"

#include <algorithm>
#include <functional>
#include <limits>

#include <Eigen/Eigenvalues>
#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include "symmetry_segmentation/quantile.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"

namespace symmetry_segmentation {
namespace {

constexpr int kPlaneIterations = 200;
// Share of the points left out at either end of an extent.
constexpr float kTrim = 0.05f;

/// Extents of `points` along their principal axes, between the kTrim and 1 - kTrim quantiles:
/// a few stray points of a neighbour or of the background do not make an object large.
template <int Dims>
Eigen::Matrix<float, Dims, 1> principalExtents(const std::vector<Eigen::Matrix<float, Dims, 1>>& points) {
  using Vector = Eigen::Matrix<float, Dims, 1>;
  using Matrix = Eigen::Matrix<float, Dims, Dims>;
  Vector mean = Vector::Zero();
  for (const Vector& p : points) mean += p;
  mean /= static_cast<float>(points.size());
  Matrix covariance = Matrix::Zero();
  for (const Vector& p : points) covariance += (p - mean) * (p - mean).transpose();
  const Matrix axes = Eigen::SelfAdjointEigenSolver<Matrix>(covariance).eigenvectors();
  Vector extents;
  std::vector<float> along(points.size());
  for (int d = 0; d < Dims; ++d) {
    for (std::size_t i = 0; i < points.size(); ++i) along[i] = axes.col(d).dot(points[i] - mean);
    extents[d] = trimmedSpan(along, kTrim);
  }
  return extents;
}

}  // namespace

Eigen::Vector3f segmentExtents(const Cloud& cloud, const std::vector<int>& points, const std::optional<Eigen::Vector3f>& up) {
  if (points.empty()) return Eigen::Vector3f::Zero();
  Eigen::Vector3f extents;
  if (up) {
    const Eigen::Vector3f normal = up->normalized();
    const Eigen::Vector3f u = normal.unitOrthogonal();
    const Eigen::Vector3f v = normal.cross(u);
    std::vector<Eigen::Vector2f> footprint;
    footprint.reserve(points.size());
    std::vector<float> heights;
    heights.reserve(points.size());
    for (int i : points) {
      const Eigen::Vector3f p = cloud[i].getVector3fMap();
      footprint.emplace_back(u.dot(p), v.dot(p));
      heights.push_back(normal.dot(p));
    }
    extents << principalExtents<2>(footprint), trimmedSpan(heights, kTrim);
  } else {
    std::vector<Eigen::Vector3f> all;
    all.reserve(points.size());
    for (int i : points) all.push_back(cloud[i].getVector3fMap());
    extents = principalExtents<3>(all);
  }
  std::sort(extents.data(), extents.data() + 3, std::greater<float>());
  return extents;
}

bool hasObjectSize(const Cloud::ConstPtr& cloud, const std::vector<int>& points, const std::optional<Eigen::Vector3f>& up,
                   const ObjectSizeParams& params, float plane_distance) {
  if (points.size() < 3) return true;
  if (params.max_extent > 0.0f && segmentExtents(*cloud, points, up)[0] > params.max_extent) return false;
  if (params.max_plane_extent <= 0.0f) return true;
  // Mostly one plane: the largest plane's share of the points, and how wide that plane is.
  const std::vector<int> on_plane = largestPlanePoints(cloud, points, plane_distance);
  if (static_cast<float>(on_plane.size()) < params.min_plane_share * static_cast<float>(points.size())) return true;
  return segmentExtents(*cloud, on_plane, std::nullopt)[0] <= params.max_plane_extent;
}

std::vector<int> largestPlanePoints(const Cloud::ConstPtr& cloud, const std::vector<int>& points, float distance) {
  if (points.size() < 3) return {};
  pcl::SACSegmentation<PointT> ransac;
  ransac.setModelType(pcl::SACMODEL_PLANE);
  ransac.setMethodType(pcl::SAC_RANSAC);
  ransac.setDistanceThreshold(distance);
  ransac.setMaxIterations(kPlaneIterations);
  ransac.setInputCloud(cloud);
  ransac.setIndices(std::make_shared<pcl::Indices>(points.begin(), points.end()));
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coefficients;
  ransac.segment(inliers, coefficients);
  return std::vector<int>(inliers.indices.begin(), inliers.indices.end());
}

float topHeight(const Cloud& cloud, const std::vector<int>& points, const PlaneCoefficients& table_plane) {
  if (points.empty()) return 0.0f;
  const float norm = table_plane.head<3>().norm();
  std::vector<float> heights;
  heights.reserve(points.size());
  for (int i : points) heights.push_back((table_plane.head<3>().dot(cloud[i].getVector3fMap()) + table_plane[3]) / norm);
  return quantileOf(heights, 1.0f - kTrim);
}

void ObjectSizeStage::run(PipelineState& state) const {
  const float plane_distance = onPlaneDistance(voxel_size_);
  const std::size_t before = state.segments.size();
  const bool check_top = params_.min_top_height > 0.0f && state.prepared.has_table;
  state.segments.erase(std::remove_if(state.segments.begin(), state.segments.end(),
                                      [&](const CandidateSegment& segment) {
                                        if (check_top && topHeight(*state.cloud, segment.points, state.prepared.table_plane) <
                                                             params_.min_top_height) {
                                          return true;
                                        }
                                        return !hasObjectSize(state.cloud, segment.points, state.up, params_, plane_distance);
                                      }),
                       state.segments.end());
  state.count("dropped", before - state.segments.size());
}

}  // namespace symmetry_segmentation
