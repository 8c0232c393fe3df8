// The supporting surface: RANSAC on a coarse copy of the cloud (the table is large and flat,
// so 1-2 cm voxels lose nothing and keep RANSAC fast on dense clouds).
//
// In a single view the table is often not the largest plane: a wall or the floor behind it can
// hold more points. So up to three large planes are extracted in turn and the one the objects
// stand on wins: the most points (not on any of the planes) within an object's height in front
// of it and over its extent. A wall has few such points, the floor only the table's legs.
#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/filters/extract_indices.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include "symmetry_segmentation/preprocessing.h"

#include <optional>

namespace symmetry_segmentation {
namespace {

constexpr int kMaxCandidatePlanes = 3;
constexpr float kMaxObjectHeight = 0.3f;   // Objects on a table are lower than this (m).
constexpr float kFootprintDistance = 0.03f;  // An object stands over the plane's points (m).
// Far from the sensor a plane's noise exceeds the RANSAC threshold; those points are still the
// plane, not something standing on another one.
constexpr float kOnPlaneFactor = 3.0f;

struct CandidatePlane {
  PlaneCoefficients plane;
  Cloud::Ptr inliers;
};

float distanceTo(const PlaneCoefficients& plane, const PointT& p) { return plane.head<3>().dot(p.getVector3fMap()) + plane[3]; }

/// The largest plane of `cloud` with at least `min_inliers` points, if any.
bool largestPlane(const Cloud::Ptr& cloud, const PreprocessParams& params, std::size_t min_inliers,
                  CandidatePlane& candidate, pcl::PointIndices& inliers) {
  if (cloud->size() < 3) return false;
  pcl::SACSegmentation<PointT> ransac;
  ransac.setOptimizeCoefficients(true);
  ransac.setModelType(pcl::SACMODEL_PLANE);
  ransac.setMethodType(pcl::SAC_RANSAC);
  ransac.setDistanceThreshold(params.ransac_distance);
  ransac.setMaxIterations(params.ransac_iterations);
  ransac.setInputCloud(cloud);
  pcl::ModelCoefficients coefficients;
  ransac.segment(inliers, coefficients);
  if (coefficients.values.size() != 4 || inliers.indices.size() < min_inliers) return false;
  PlaneCoefficients plane(coefficients.values[0], coefficients.values[1], coefficients.values[2], coefficients.values[3]);
  const float norm = plane.head<3>().norm();
  if (!(norm > 1e-6f)) return false;
  candidate.plane = plane / norm;
  candidate.inliers = std::make_shared<Cloud>();
  pcl::ExtractIndices<PointT> extract;
  extract.setInputCloud(cloud);
  extract.setIndices(std::make_shared<pcl::PointIndices>(inliers));
  extract.filter(*candidate.inliers);
  return true;
}

/// Points resting on the plane: on no candidate plane, on the sensor's side within an object's
/// height, and over the plane's own points. (The sensor sees the table from above.)
std::size_t pointsStandingOn(const CandidatePlane& candidate, const std::vector<CandidatePlane>& all,
                             const Cloud& cloud, const std::optional<Eigen::Vector3f>& viewpoint,
                             float on_plane_distance) {
  std::vector<const PointT*> off_planes;
  float majority = 0.0f;
  for (const auto& p : cloud.points) {
    bool on_any = false;
    for (const auto& other : all) on_any = on_any || std::fabs(distanceTo(other.plane, p)) <= on_plane_distance;
    if (on_any) continue;
    off_planes.push_back(&p);
    majority += distanceTo(candidate.plane, p) > 0.0f ? 1.0f : -1.0f;
  }
  // Up is the sensor's side, or without a known sensor the side most other points are on (as
  // preprocessing orients the plane it keeps).
  const float side = viewpoint ? candidate.plane.head<3>().dot(*viewpoint) + candidate.plane[3] : majority;
  const PlaneCoefficients up = side >= 0.0f ? candidate.plane : PlaneCoefficients(-candidate.plane);
  pcl::KdTreeFLANN<PointT> footprint;
  footprint.setInputCloud(candidate.inliers);
  std::vector<int> index(1);
  std::vector<float> squared(1);
  std::size_t standing = 0;
  for (const PointT* p : off_planes) {
    const float height = distanceTo(up, *p);
    if (height <= 0.0f || height > kMaxObjectHeight) continue;
    PointT foot = *p;
    foot.getVector3fMap() -= height * up.head<3>();
    if (footprint.nearestKSearch(foot, 1, index, squared) == 1 && squared[0] < kFootprintDistance * kFootprintDistance) {
      ++standing;
    }
  }
  return standing;
}

}  // namespace

bool estimateSupportingPlane(const Cloud& cloud, const PreprocessParams& params,
                             const std::optional<Eigen::Vector3f>& viewpoint, PlaneCoefficients& plane) {
  if (cloud.size() < 3) return false;
  // A "table" holding under a tenth of the scene is more likely an object face.
  const std::size_t min_inliers = std::max<std::size_t>(50, cloud.size() / 10);
  std::vector<CandidatePlane> candidates;
  Cloud::Ptr remaining = cloud.makeShared();
  for (int k = 0; k < kMaxCandidatePlanes; ++k) {
    CandidatePlane candidate;
    pcl::PointIndices inliers;
    if (!largestPlane(remaining, params, min_inliers, candidate, inliers)) break;
    candidates.push_back(candidate);
    pcl::ExtractIndices<PointT> extract;
    extract.setInputCloud(remaining);
    extract.setIndices(std::make_shared<pcl::PointIndices>(inliers));
    extract.setNegative(true);
    auto rest = std::make_shared<Cloud>();
    extract.filter(*rest);
    remaining = rest;
  }
  if (candidates.empty()) return false;
  std::size_t best = 0, best_standing = 0;
  for (std::size_t k = 0; k < candidates.size() && candidates.size() > 1; ++k) {
    const std::size_t standing = pointsStandingOn(candidates[k], candidates, cloud, viewpoint, kOnPlaneFactor * params.ransac_distance);
    if (standing > best_standing) {  // Ties keep the larger (earlier) plane.
      best_standing = standing;
      best = k;
    }
  }
  plane = candidates[best].plane;
  return true;
}

}  // namespace symmetry_segmentation
