#include "symmetry_segmentation/symmetry/plane_refinement.h"

#include <pcl/search/kdtree.h>
#include <pcl/registration/correspondence_rejection_one_to_one.h>
#include <pcl/registration/icp.h>
#include <pcl/registration/transformation_estimation_point_to_plane_lls.h>

#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {
namespace {

// A refinement that turns the plane by more than this found another symmetry, not a better
// estimate of this one.
constexpr float kMaxRefinementAngleDeg = 15.0f;
constexpr std::size_t kMinSegmentPoints = 10;
// ICP needs most of the mirrored segment to find counterparts to be meaningful; below this the
// plane is not a symmetry of the segment and there is nothing to refine.
constexpr float kMinMatchedFraction = 0.5f;

std::size_t countWithNeighbour(const pcl::search::KdTree<PointT>& tree, const Cloud& queries, float radius) {
  std::vector<int> index(1);
  std::vector<float> squared(1);
  std::size_t matched = 0;
  for (const auto& q : queries.points) {
    if (tree.nearestKSearch(q, 1, index, squared) == 1 && squared[0] <= radius * radius) ++matched;
  }
  return matched;
}

}  // namespace

SymmetryPlane refinePlane(const Cloud& cloud, const std::vector<int>& segment, const SymmetryPlane& plane,
                          const SymmetryRefinementParams& refinement, const SymmetryDetectionParams& detection) {
  if (!refinement.enabled || segment.size() < kMinSegmentPoints) return plane;
  auto target = std::make_shared<Cloud>();
  auto mirrored = std::make_shared<Cloud>();
  target->reserve(segment.size());
  mirrored->reserve(segment.size());
  for (int index : segment) {
    const PointT& p = cloud.points[index];
    target->push_back(p);
    PointT q = p;
    q.getVector3fMap() = reflectPoint(plane, p.getVector3fMap());
    q.getNormalVector3fMap() = reflectDirection(plane, p.getNormalVector3fMap());
    mirrored->push_back(q);
  }

  auto target_tree = std::make_shared<pcl::search::KdTree<PointT>>();
  target_tree->setInputCloud(target);
  if (countWithNeighbour(*target_tree, *mirrored, refinement.icp_max_correspondence) <
      kMinMatchedFraction * static_cast<float>(mirrored->size())) {
    return plane;
  }

  pcl::IterativeClosestPoint<PointT, PointT> icp;
  icp.setSearchMethodTarget(target_tree, true);  // built above: do not build it again
  icp.setTransformationEstimation(
      std::make_shared<pcl::registration::TransformationEstimationPointToPlaneLLS<PointT, PointT>>());
  icp.addCorrespondenceRejector(std::make_shared<pcl::registration::CorrespondenceRejectorOneToOne>());
  icp.setMaximumIterations(refinement.icp_iterations);
  icp.setMaxCorrespondenceDistance(refinement.icp_max_correspondence);
  icp.setInputSource(mirrored);
  icp.setInputTarget(target);
  Cloud aligned;
  icp.align(aligned);
  if (!icp.hasConverged()) return plane;

  // Point i and the aligned image of its reflection are mirror images under the refined plane.
  std::vector<PlaneSample> samples;
  samples.reserve(segment.size());
  for (std::size_t i = 0; i < segment.size(); ++i) {
    const Eigen::Vector3f p = target->points[i].getVector3fMap();
    const Eigen::Vector3f image = aligned.points[i].getVector3fMap();
    if ((image - p).norm() < detection.min_match_distance) continue;  // too close to the plane to tell
    PlaneSample sample;
    sample.plane = canonicalPlane(bisectorPlane(p, image));
    samples.push_back(sample);
  }
  const auto modes = meanShiftPlanes(samples, detection.mean_shift_angle_deg, detection.mean_shift_distance);
  if (modes.empty()) return plane;
  const SymmetryPlane refined = modes.front().plane;
  if (planeAngleDeg(refined, plane) > kMaxRefinementAngleDeg) return plane;
  return refined;
}

}  // namespace symmetry_segmentation
