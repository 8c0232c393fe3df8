// The supporting surface: RANSAC on a coarse copy of the cloud (the table is large and flat,
// so 1-2 cm voxels lose nothing and keep RANSAC fast on dense clouds).
//
// In a single view the table is often not the largest plane: a wall or the floor behind it can
// hold more points. So up to three large planes are extracted in turn and the one the objects
// stand on wins: the most points (not on any of the planes) within an object's height in front
// of it and over its extent. A wall has few such points, the floor only the table's legs.
//
// In a fused scene cropped to the tabletop the table may be only a rim around the objects, far
// smaller than their faces (kinfu_tabletop: 5 % of the points). Whatever the table's size, the
// whole scene lies on one side of it: it is a face of the scene's convex hull. So the hull faces
// holding the most points are candidates too.
#include <pcl/PointIndices.h>
#include <pcl/filters/extract_indices.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/surface/convex_hull.h>

#include "symmetry_segmentation/plane_fit.h"
#include "symmetry_segmentation/preprocessing.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace symmetry_segmentation {
namespace {

constexpr int kMaxCandidatePlanes = 3;
// With gravity known, walls and box faces found first are passed over: look a little further.
constexpr int kMaxCandidatePlanesWithUp = 5;
constexpr int kMaxHullCandidates = 3;
// Points seen under a candidate's own points that still let it be the support (noise, legs).
constexpr std::size_t kMaxPointsUnderSupport = 20;
constexpr std::size_t kMinNormalsToJudge = 10;
// Hull faces closer than this in angle (cos) and offset are one candidate.
constexpr float kSamePlaneCos = 0.99f;
constexpr float kSamePlaneOffset = 0.02f;
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
  const auto plane = fitLargestPlane(cloud, params.ransac_distance, params.ransac_iterations, inliers);
  if (!plane || inliers.indices.size() < min_inliers) return false;
  candidate.plane = *plane;
  candidate.inliers = std::make_shared<Cloud>();
  pcl::ExtractIndices<PointT> extract;
  extract.setInputCloud(cloud);
  extract.setIndices(std::make_shared<pcl::PointIndices>(inliers));
  extract.filter(*candidate.inliers);
  return true;
}

bool samePlane(const PlaneCoefficients& a, const PlaneCoefficients& b) {
  const float cos = a.head<3>().dot(b.head<3>());
  return std::fabs(cos) > kSamePlaneCos && std::fabs(cos > 0.0f ? a[3] - b[3] : a[3] + b[3]) < kSamePlaneOffset;
}

/// The faces of the convex hull of `cloud` holding the most points within ransac_distance (at
/// least `min_inliers`), each re-fitted to its points, as candidates; none when the hull fails
/// (a flat or degenerate cloud).
std::vector<CandidatePlane> hullFacePlanes(const Cloud::Ptr& cloud, const PreprocessParams& params, std::size_t min_inliers) {
  std::vector<CandidatePlane> result;
  if (cloud->size() < 4) return result;
  pcl::ConvexHull<PointT> hull;
  hull.setDimension(3);
  hull.setInputCloud(cloud);
  Cloud hull_points;
  std::vector<pcl::Vertices> faces;
  hull.reconstruct(hull_points, faces);
  if (hull.getDimension() != 3) return result;

  struct Face {
    std::size_t inliers;
    PlaneCoefficients plane;
  };
  std::vector<Face> scored;
  for (const pcl::Vertices& face : faces) {
    if (face.vertices.size() < 3) continue;
    const Eigen::Vector3f a = hull_points[face.vertices[0]].getVector3fMap();
    const Eigen::Vector3f b = hull_points[face.vertices[1]].getVector3fMap();
    const Eigen::Vector3f c = hull_points[face.vertices[2]].getVector3fMap();
    Eigen::Vector3f normal = (b - a).cross(c - a);
    if (!(normal.norm() > 1e-9f)) continue;
    normal.normalize();
    const PlaneCoefficients plane(normal.x(), normal.y(), normal.z(), -normal.dot(a));
    std::size_t inliers = 0;
    for (const auto& p : cloud->points) inliers += std::fabs(distanceTo(plane, p)) <= params.ransac_distance;
    if (inliers >= min_inliers) scored.push_back({inliers, plane});
  }
  std::sort(scored.begin(), scored.end(), [](const Face& x, const Face& y) { return x.inliers > y.inliers; });

  std::vector<PlaneCoefficients> taken;
  for (const Face& face : scored) {
    if (static_cast<int>(result.size()) >= kMaxHullCandidates) break;
    if (std::any_of(taken.begin(), taken.end(), [&](const PlaneCoefficients& t) { return samePlane(t, face.plane); })) continue;
    taken.push_back(face.plane);
    // A hull face rests on a few extreme points; the plane through all of its points is the table.
    auto near = std::make_shared<Cloud>();
    for (const auto& p : cloud->points) {
      if (std::fabs(distanceTo(face.plane, p)) <= 2.0f * params.ransac_distance) near->push_back(p);
    }
    CandidatePlane candidate;
    pcl::PointIndices inliers;
    if (largestPlane(near, params, min_inliers, candidate, inliers)) result.push_back(candidate);
  }
  return result;
}

/// How a candidate relates to the rest of the scene.
struct Support {
  std::size_t standing = 0;  ///< Points resting on it (see below).
  std::size_t under = 0;     ///< Points below it, under its own points.
  bool faces_down = false;   ///< Its points' normals (where known) point away from "up".
};

/// Points resting on the plane: on no candidate plane, on the sensor's side within an object's
/// height, and over the plane's own points. (The sensor sees the table from above.) And points
/// under the plane's own points on the other side: nothing is seen through or under a table
/// top, while a plane through an object's face has the rest of the scene on both sides.
Support supportOf(const CandidatePlane& candidate, const std::vector<CandidatePlane>& all, const Cloud& cloud,
                  const std::optional<Eigen::Vector3f>& viewpoint, const std::optional<Eigen::Vector3f>& gravity_up,
                  float on_plane_distance, bool single_view) {
  std::vector<const PointT*> off_planes;
  float majority = 0.0f;
  for (const auto& p : cloud.points) {
    bool on_any = false;
    for (const auto& other : all) on_any = on_any || std::fabs(distanceTo(other.plane, p)) <= on_plane_distance;
    if (on_any) continue;
    off_planes.push_back(&p);
    majority += distanceTo(candidate.plane, p) > 0.0f ? 1.0f : -1.0f;
  }
  // Up is gravity's where known, else the sensor's side, or without a known sensor the side most
  // other points are on (as preprocessing orients the plane it keeps).
  const float side = gravity_up ? candidate.plane.head<3>().dot(*gravity_up)
                     : viewpoint ? candidate.plane.head<3>().dot(*viewpoint) + candidate.plane[3]
                                 : majority;
  const PlaneCoefficients up = side >= 0.0f ? candidate.plane : PlaneCoefficients(-candidate.plane);
  pcl::KdTreeFLANN<PointT> footprint;
  footprint.setInputCloud(candidate.inliers);
  std::vector<int> index(1);
  std::vector<float> squared(1);
  auto overPlanePoints = [&](const PointT& p, float height) {
    PointT foot = p;
    foot.getVector3fMap() -= height * up.head<3>();
    return footprint.nearestKSearch(foot, 1, index, squared) == 1 && squared[0] < kFootprintDistance * kFootprintDistance;
  };
  Support support;
  for (const PointT* p : off_planes) {
    const float height = distanceTo(up, *p);
    if (height <= 0.0f || height > kMaxObjectHeight) continue;
    if (overPlanePoints(*p, height)) ++support.standing;
  }
  // One sensor above a plane never sees under its points, only past its edges; there the
  // footprint test counts what stands beside the table below it (the floor, a chair, the foot
  // of the wall, whose strip crossing the plane counts as the plane's points) and says nothing.
  if (!single_view) {
    for (const auto& p : cloud.points) {
      const float height = distanceTo(up, p);
      if (height < -on_plane_distance && overPlanePoints(p, height)) ++support.under;
    }
  }
  // A fused cloud's normals point out of the surfaces: a table's point up, toward what stands
  // on it; the far face of a box, seen from another side, points away.
  float agreement = 0.0f;
  std::size_t with_normals = 0;
  for (const auto& p : candidate.inliers->points) {
    if (!std::isfinite(p.normal_x) || !std::isfinite(p.normal_y) || !std::isfinite(p.normal_z)) continue;
    agreement += up.head<3>().dot(p.getNormalVector3fMap());
    ++with_normals;
  }
  support.faces_down = with_normals >= kMinNormalsToJudge && agreement < 0.0f;
  return support;
}

}  // namespace

bool estimateSupportingPlane(const Cloud& cloud, const PreprocessParams& params,
                             const std::optional<Eigen::Vector3f>& viewpoint, PlaneCoefficients& plane,
                             bool single_view, const std::optional<Eigen::Vector3f>& up) {
  if (cloud.size() < 3) return false;
  // A "table" holding under a tenth of the scene is more likely an object face.
  const std::size_t min_inliers = std::max<std::size_t>(50, cloud.size() / 10);
  // With gravity known, a wall or a tilted face is no table however many points it holds; it is
  // still taken out of the cloud so that the next plane can be found.
  const float min_up_cos = std::cos(params.max_support_tilt * static_cast<float>(M_PI) / 180.0f);
  auto facesUp = [&](const CandidatePlane& candidate) {
    return !up || std::fabs(candidate.plane.head<3>().dot(up->normalized())) >= min_up_cos;
  };
  const int max_planes = up ? kMaxCandidatePlanesWithUp : kMaxCandidatePlanes;
  std::vector<CandidatePlane> candidates;
  Cloud::Ptr remaining = cloud.makeShared();
  for (int k = 0; k < max_planes; ++k) {
    CandidatePlane candidate;
    pcl::PointIndices inliers;
    if (!largestPlane(remaining, params, min_inliers, candidate, inliers)) break;
    // A plane next to an earlier, larger one is that surface again: what RANSAC finds through
    // the rest of its noise and the lowest points standing on it (books lying on the table
    // tilt it by a degree or two). As a candidate of its own it would take those points from
    // every candidate's count of what stands on it and could win over the table it lies in.
    const bool again = std::any_of(candidates.begin(), candidates.end(),
                                   [&](const CandidatePlane& c) { return samePlane(c.plane, candidate.plane); });
    if (facesUp(candidate) && !again) candidates.push_back(candidate);
    pcl::ExtractIndices<PointT> extract;
    extract.setInputCloud(remaining);
    extract.setIndices(std::make_shared<pcl::PointIndices>(inliers));
    extract.setNegative(true);
    auto rest = std::make_shared<Cloud>();
    extract.filter(*rest);
    remaining = rest;
  }
  for (CandidatePlane& hull_candidate : hullFacePlanes(cloud.makeShared(), params, 50)) {
    const bool known = std::any_of(candidates.begin(), candidates.end(),
                                   [&](const CandidatePlane& c) { return samePlane(c.plane, hull_candidate.plane); });
    if (!known && facesUp(hull_candidate)) candidates.push_back(std::move(hull_candidate));
  }
  if (candidates.empty()) return false;
  // A support has (almost) nothing under its own points and faces up; if no candidate
  // qualifies, all compete.
  std::vector<Support> supports;
  for (const CandidatePlane& candidate : candidates) {
    supports.push_back(
        supportOf(candidate, candidates, cloud, viewpoint, up, kOnPlaneFactor * params.ransac_distance, single_view));
  }
  auto supportsThings = [&](std::size_t k) {
    return !supports[k].faces_down &&
           supports[k].under <= std::max<std::size_t>(kMaxPointsUnderSupport, candidates[k].inliers->size() / 20);
  };
  bool any_support = false;
  for (std::size_t k = 0; k < candidates.size(); ++k) any_support = any_support || supportsThings(k);
  std::size_t best = 0, best_standing = 0;
  bool have_best = false;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    if (any_support && !supportsThings(k)) continue;
    // Ties keep the larger (earlier) plane.
    if (!have_best || supports[k].standing > best_standing) {
      best = k;
      best_standing = supports[k].standing;
      have_best = true;
    }
  }
  plane = candidates[best].plane;
  return true;
}

}  // namespace symmetry_segmentation
