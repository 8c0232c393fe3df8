#include "symmetry_segmentation/plane_refinement.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Eigenvalues>

#include "symmetry_segmentation/quantile.h"

namespace symmetry_segmentation {
namespace {

constexpr int kRounds = 3;
constexpr float kInlierSigmas = 3.0f;
// Below this a square's noise is taken as this (m): the points of a flat patch averaged into
// voxels can agree to a fraction of a millimetre, and one such square must not outweigh the rest.
constexpr float kMinSigma = 0.001f;
constexpr std::size_t kMinPointsPerCell = 5;

std::int64_t cellKey(float u, float v, float cell) {
  const auto iu = static_cast<std::int64_t>(std::floor(u / cell));
  const auto iv = static_cast<std::int64_t>(std::floor(v / cell));
  return (iu << 32) ^ (iv & 0xffffffffLL);
}

/// One round: the weighted fit, or nothing when too few points count.
bool refitOnce(const Cloud& cloud, PlaneCoefficients& plane, float band, float cell, std::size_t min_points) {
  const Eigen::Vector3f normal = plane.head<3>();
  const Eigen::Vector3f u_axis = normal.unitOrthogonal();
  const Eigen::Vector3f v_axis = normal.cross(u_axis);
  std::unordered_map<std::int64_t, std::vector<int>> cells;
  std::vector<float> height(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3f p = cloud.points[i].getVector3fMap();
    height[i] = normal.dot(p) + plane[3];
    if (!std::isfinite(height[i]) || std::fabs(height[i]) > band) continue;
    cells[cellKey(u_axis.dot(p), v_axis.dot(p), cell)].push_back(static_cast<int>(i));
  }
  Eigen::Vector3d weighted_sum = Eigen::Vector3d::Zero();
  double weight_sum = 0.0;
  struct Inlier {
    int index;
    double weight;
  };
  std::vector<Inlier> inliers;
  for (const auto& [key, members] : cells) {
    if (members.size() < kMinPointsPerCell) continue;
    std::vector<float> values;
    for (int i : members) values.push_back(height[i]);
    const float median = quantileOf(values, 0.5f);
    for (float& value : values) value = std::fabs(value - median);
    const float sigma = std::max(kMinSigma, 1.4826f * quantileOf(values, 0.5f));
    const double weight = 1.0 / (static_cast<double>(sigma) * sigma);
    for (int i : members) {
      if (std::fabs(height[i]) > kInlierSigmas * sigma) continue;
      inliers.push_back({i, weight});
      weighted_sum += weight * cloud.points[i].getVector3fMap().cast<double>();
      weight_sum += weight;
    }
  }
  if (inliers.size() < std::max<std::size_t>(3, min_points)) return false;
  const Eigen::Vector3d centroid = weighted_sum / weight_sum;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Inlier& inlier : inliers) {
    const Eigen::Vector3d d = cloud.points[inlier.index].getVector3fMap().cast<double>() - centroid;
    scatter += inlier.weight * d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  Eigen::Vector3d refit = solver.eigenvectors().col(0);  // smallest eigenvalue first
  if (refit.dot(normal.cast<double>()) < 0.0) refit = -refit;
  plane.head<3>() = refit.cast<float>();
  plane[3] = static_cast<float>(-refit.dot(centroid));
  return true;
}

}  // namespace

PlaneCoefficients refineToRegionalNoise(const Cloud& cloud, const PlaneCoefficients& plane, float band, float cell,
                                        std::size_t min_points, float max_turn_deg) {
  PlaneCoefficients refined = plane;
  refined /= plane.head<3>().norm();
  const PlaneCoefficients start = refined;
  for (int round = 0; round < kRounds; ++round) {
    if (!refitOnce(cloud, refined, band, cell, min_points)) return plane;
  }
  const float cos_turn = std::clamp(refined.head<3>().dot(start.head<3>()), -1.0f, 1.0f);
  if (std::acos(cos_turn) * 180.0f / static_cast<float>(M_PI) > max_turn_deg) return plane;
  return refined;
}

}  // namespace symmetry_segmentation
