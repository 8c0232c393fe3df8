// Background surfaces (see the header): planes found in turn by RANSAC among the candidate
// points, each split into connected patches, a patch judged by its extent, how fully it covers
// it, and whether it leaves the tabletop region.
#include "symmetry_segmentation/background_surfaces.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include <Eigen/Eigenvalues>
#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>
#include <pcl/segmentation/sac_segmentation.h>

#include "symmetry_segmentation/quantile.h"

namespace symmetry_segmentation {
namespace {

// Planes tried; a scene seldom has more large flat surfaces than this besides the table.
constexpr int kMaxPlanes = 8;
constexpr std::size_t kMinPlanePoints = 30;
// A patch covers at least this share of the rectangle its extent spans (a wall partly hidden by
// objects still does; a plane slicing through objects meets thin rings of them).
constexpr float kMinCover = 0.3f;
// A surface's points have mostly its own points around them (see flatShare).
constexpr float kMinFlatShare = 0.75f;
// Share of the points left out at either end of an extent (a few strays do not make it wide).
constexpr float kTrim = 0.02f;

struct PatchShape {
  float length = 0.0f;  ///< Extent along the patch's main in-plane axis (m).
  float width = 0.0f;   ///< Extent across it, in the plane (m).
  float cover = 0.0f;   ///< Share of length x width its points' cells fill.
};

PatchShape shapeOf(const Cloud& cloud, const std::vector<int>& points, const Eigen::Vector3f& normal, float cell) {
  const Eigen::Vector3f u0 = normal.unitOrthogonal();
  const Eigen::Vector3f v0 = normal.cross(u0);
  std::vector<Eigen::Vector2f> flat;
  flat.reserve(points.size());
  Eigen::Vector2f mean = Eigen::Vector2f::Zero();
  for (int i : points) {
    const Eigen::Vector3f p = cloud[i].getVector3fMap();
    flat.emplace_back(u0.dot(p), v0.dot(p));
    mean += flat.back();
  }
  mean /= static_cast<float>(flat.size());
  Eigen::Matrix2f covariance = Eigen::Matrix2f::Zero();
  for (const Eigen::Vector2f& p : flat) covariance += (p - mean) * (p - mean).transpose();
  const Eigen::Matrix2f axes = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2f>(covariance).eigenvectors();
  PatchShape shape;
  std::vector<float> along(flat.size());
  for (std::size_t k = 0; k < flat.size(); ++k) along[k] = axes.col(1).dot(flat[k] - mean);
  shape.length = trimmedSpan(along, kTrim);
  for (std::size_t k = 0; k < flat.size(); ++k) along[k] = axes.col(0).dot(flat[k] - mean);
  shape.width = trimmedSpan(along, kTrim);
  // Cells of a grid in the plane that hold a point, against the cells of the extent's rectangle.
  std::unordered_set<long long> cells;
  for (const Eigen::Vector2f& p : flat) {
    const auto a = static_cast<long long>(std::floor(p.x() / cell));
    const auto b = static_cast<long long>(std::floor(p.y() / cell));
    cells.insert(a * 1000003LL + b);
  }
  const float rectangle_cells = std::max(1.0f, (shape.length / cell + 1.0f) * (shape.width / cell + 1.0f));
  shape.cover = std::min(1.0f, static_cast<float>(cells.size()) / rectangle_cells);
  return shape;
}

/// Mean share, over `points`, of their candidate neighbours within connect_distance that lie on
/// `plane`: a wall's neighbourhood is the wall; the front line of a row of cans, where a plane
/// grazes them, has the rest of each can curving away behind it.
float flatShare(const Cloud& cloud, const pcl::search::KdTree<PointT>& search, const std::vector<int>& points,
                const Eigen::Vector4f& plane, const BackgroundSurfaceParams& params) {
  pcl::Indices neighbours;
  std::vector<float> squared;
  double sum = 0.0;
  for (int i : points) {
    if (search.radiusSearch(cloud[i], params.connect_distance, neighbours, squared) <= 0) continue;
    std::size_t flat = 0;
    for (int j : neighbours) flat += std::fabs(plane.head<3>().dot(cloud[j].getVector3fMap()) + plane[3]) <= params.ransac_distance;
    sum += static_cast<double>(flat) / static_cast<double>(neighbours.size());
  }
  return static_cast<float>(sum / static_cast<double>(points.size()));
}

}  // namespace

std::vector<bool> backgroundSurfacePoints(const Cloud& cloud, const std::vector<bool>& candidate,
                                          const std::vector<bool>& in_region, const BackgroundSurfaceParams& params) {
  std::vector<bool> background(cloud.size(), false);
  if (!(params.max_object_extent > 0.0f)) return background;
  auto remaining = std::make_shared<pcl::Indices>();
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (candidate[i]) remaining->push_back(static_cast<int>(i));
  }
  auto shared = cloud.makeShared();
  pcl::search::KdTree<PointT> search;
  search.setInputCloud(shared, std::make_shared<pcl::Indices>(*remaining));
  const float cell = params.connect_distance / 3.0f;
  for (int plane_number = 0; plane_number < kMaxPlanes && remaining->size() >= kMinPlanePoints; ++plane_number) {
    pcl::SACSegmentation<PointT> ransac;
    ransac.setOptimizeCoefficients(true);
    ransac.setModelType(pcl::SACMODEL_PLANE);
    ransac.setMethodType(pcl::SAC_RANSAC);
    ransac.setDistanceThreshold(params.ransac_distance);
    ransac.setMaxIterations(params.ransac_iterations);
    ransac.setInputCloud(shared);
    ransac.setIndices(remaining);
    pcl::PointIndices inliers;
    pcl::ModelCoefficients coefficients;
    ransac.segment(inliers, coefficients);
    if (coefficients.values.size() != 4 || inliers.indices.size() < kMinPlanePoints) break;
    Eigen::Vector4f plane(coefficients.values[0], coefficients.values[1], coefficients.values[2], coefficients.values[3]);
    if (!(plane.head<3>().norm() > 1e-6f)) break;
    plane /= plane.head<3>().norm();
    const Eigen::Vector3f normal = plane.head<3>();

    pcl::EuclideanClusterExtraction<PointT> patches;
    patches.setClusterTolerance(params.connect_distance);
    patches.setMinClusterSize(static_cast<int>(kMinPlanePoints));
    patches.setSearchMethod(std::make_shared<pcl::search::KdTree<PointT>>());
    patches.setInputCloud(shared);
    patches.setIndices(std::make_shared<pcl::Indices>(inliers.indices));
    std::vector<pcl::PointIndices> found;
    patches.extract(found);
    for (const pcl::PointIndices& patch : found) {
      std::size_t inside = 0;
      for (int i : patch.indices) inside += in_region[i];
      if (inside == 0 || inside == patch.indices.size()) continue;
      const std::vector<int> points(patch.indices.begin(), patch.indices.end());
      const PatchShape shape = shapeOf(cloud, points, normal, cell);
      if (shape.length <= params.max_object_extent || shape.cover < kMinCover) continue;
      if (flatShare(*shared, search, points, plane, params) < kMinFlatShare) continue;
      for (int i : points) background[i] = true;
    }
    // The plane's points are done with, background or not.
    std::vector<bool> on_plane(cloud.size(), false);
    for (int i : inliers.indices) on_plane[i] = true;
    remaining->erase(std::remove_if(remaining->begin(), remaining->end(), [&](int i) { return on_plane[i]; }),
                     remaining->end());
  }
  return background;
}

}  // namespace symmetry_segmentation
