// Stage 16, coaxial_pieces: pieces of one surface of revolution seen apart are joined (see the header).
#include "symmetry_segmentation/symmetry/coaxial_pieces.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>

#include <pcl/kdtree/kdtree_flann.h>

#include "symmetry_segmentation/symmetry/duplicate_segments.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/upright_hypotheses.h"

namespace symmetry_segmentation {

std::pair<Eigen::Vector3f, float> closestApproach(const Cloud& cloud, const std::vector<int>& first,
                                                  const std::vector<int>& second) {
  if (first.empty() || second.empty()) return {Eigen::Vector3f::Zero(), std::numeric_limits<float>::infinity()};
  pcl::PointCloud<pcl::PointXYZ>::Ptr first_points(new pcl::PointCloud<pcl::PointXYZ>);
  for (int i : first) first_points->push_back(pcl::PointXYZ(cloud[i].x, cloud[i].y, cloud[i].z));
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(first_points);
  std::vector<int> nearest(1);
  std::vector<float> squared_distance(1);
  float best = std::numeric_limits<float>::max();
  Eigen::Vector3f middle = Eigen::Vector3f::Zero();
  for (int i : second) {
    const pcl::PointXYZ query(cloud[i].x, cloud[i].y, cloud[i].z);
    if (tree.nearestKSearch(query, 1, nearest, squared_distance) < 1 || squared_distance[0] >= best) continue;
    best = squared_distance[0];
    middle = 0.5f * (cloud[i].getVector3fMap() + (*first_points)[nearest[0]].getVector3fMap());
  }
  return {middle, std::sqrt(best)};
}

std::optional<Eigen::Vector3f> CoaxialPieceStage::revolutionAxis(const Cloud& cloud, const std::vector<int>& points,
                                                                 const Eigen::Vector3f& up) const {
  const auto axes = fitVerticalAxes(cloud, points, up, axes_);
  if (axes.empty()) return std::nullopt;
  // Most side points' normal lines must pass the axis: a box's faces have normal lines that
  // cross near its centre line, and its rounded edges' normals turn, but most miss it.
  const Eigen::Vector3f& axis = axes.front().point;
  std::size_t sides = 0, through = 0;
  for (int i : points) {
    Eigen::Vector3f normal = cloud[i].getNormalVector3fMap();
    normal -= normal.dot(up) * up;
    if (normal.norm() < 0.3f) continue;  // a near-horizontal surface point: no side
    ++sides;
    Eigen::Vector3f offset = axis - cloud[i].getVector3fMap();
    offset -= offset.dot(up) * up;
    through += std::fabs(up.cross(normal.normalized()).dot(offset)) < axes_.max_axis_residual;
  }
  if (sides == 0 || static_cast<float>(through) < params_.min_axis_share * static_cast<float>(sides)) return std::nullopt;
  return axis;
}

void CoaxialPieceStage::run(PipelineState& state) const {
  std::size_t joined = 0;
  if (!state.up) {
    state.count("joined", joined);
    return;
  }
  const Eigen::Vector3f up = *state.up;
  const Cloud& cloud = *state.cloud;
  std::vector<std::optional<Eigen::Vector3f>> axis(state.segments.size());
  for (std::size_t s = 0; s < state.segments.size(); ++s) axis[s] = revolutionAxis(cloud, state.segments[s].points, up);
  std::vector<CandidateSegment> unions;
  for (std::size_t a = 0; a < state.segments.size(); ++a) {
    for (std::size_t b = a + 1; b < state.segments.size(); ++b) {
      if (!axis[a] || !axis[b]) continue;
      Eigen::Vector3f apart = *axis[a] - *axis[b];
      apart -= apart.dot(up) * up;
      if (apart.norm() > params_.max_axis_distance) continue;
      const CandidateSegment& first = state.segments[a];
      const CandidateSegment& second = state.segments[b];
      if (overlapOfSmaller(first.points, second.points) > dedup_.max_overlap) continue;  // one piece already
      const auto [middle, gap] = closestApproach(cloud, first.points, second.points);
      if (gap > params_.max_gap || state.occupancy->classify(middle) == Occupancy::Free) continue;
      CandidateSegment joint;
      std::set_union(first.points.begin(), first.points.end(), second.points.begin(), second.points.end(),
                     std::back_inserter(joint.points));
      // Every vertical plane through the shared axis is a symmetry: either piece's will do.
      bool scored = false;
      for (const CandidateSegment* piece : {&first, &second}) {
        const SegmentScores scores = state.evidence->scores(joint.points, piece->plane);
        if (!scored || scores.occlusion > joint.scores.occlusion) {
          scored = true;
          joint.plane = piece->plane;
          joint.scores = scores;
        }
      }
      if (passesFilter(joint, filter_)) unions.push_back(std::move(joint));
    }
  }
  joined = unions.size();
  for (CandidateSegment& joint : unions) state.segments.push_back(std::move(joint));
  state.count("joined", joined);
}

}  // namespace symmetry_segmentation
