// Stage 16, coaxial_pieces: pieces of one surface of revolution seen apart are joined (see the header).
#include "symmetry_segmentation/symmetry/coaxial_pieces.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>

#include <pcl/kdtree/kdtree_flann.h>

#include "symmetry_segmentation/quantile.h"
#include "symmetry_segmentation/symmetry/duplicate_segments.h"
#include "symmetry_segmentation/symmetry/handle_pieces.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"
#include "symmetry_segmentation/symmetry/upright_hypotheses.h"

namespace symmetry_segmentation {
namespace {

// Share of a segment's points left out at its top and bottom: a stray point moves no end.
constexpr float kHeightTrim = 0.05f;

}  // namespace

std::pair<Eigen::Vector3f, float> closestApproach(const Cloud& cloud, const std::vector<int>& first,
                                                  const std::vector<int>& second) {
  if (first.empty() || second.empty()) return {Eigen::Vector3f::Zero(), std::numeric_limits<float>::infinity()};
  auto first_points = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();  // new and delete alike (ASan)
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

std::optional<Eigen::Vector3f> revolutionAxis(const Cloud& cloud, const std::vector<int>& points,
                                              const Eigen::Vector3f& up, const UprightHypothesisParams& axes_params,
                                              float min_axis_share) {
  const auto axes = fitVerticalAxes(cloud, points, up, axes_params);
  if (axes.empty()) return std::nullopt;
  // Most side points' normal lines must pass the axis: a box's faces have normal lines that
  // cross near its centre line, and its rounded edges' normals turn, but most miss it.
  const Eigen::Vector3f& axis = axes.front().point;
  std::size_t sides = 0, through = 0;
  for (int i : points) {
    Eigen::Vector3f normal;
    if (!horizontalNormal(cloud, i, up, normal)) continue;
    ++sides;
    Eigen::Vector3f offset = axis - cloud[i].getVector3fMap();
    offset -= offset.dot(up) * up;
    through += std::fabs(up.cross(normal).dot(offset)) < axes_params.max_axis_residual;
  }
  if (sides == 0 || static_cast<float>(through) < min_axis_share * static_cast<float>(sides)) return std::nullopt;
  return axis;
}

std::pair<float, float> heightRange(const Cloud& cloud, const std::vector<int>& points, const Eigen::Vector3f& up) {
  std::vector<float> heights;
  heights.reserve(points.size());
  for (int i : points) heights.push_back(up.dot(cloud[i].getVector3fMap()));
  return trimmedRange(heights, kHeightTrim);
}

float rangeOverlap(const std::pair<float, float>& first, const std::pair<float, float>& second) {
  const float shorter = std::min(first.second - first.first, second.second - second.first);
  if (!(shorter > 0.0f)) return 0.0f;
  return std::max(0.0f, std::min(first.second, second.second) - std::max(first.first, second.first)) / shorter;
}

float heightOverlap(const Cloud& cloud, const std::vector<int>& first, const std::vector<int>& second,
                    const Eigen::Vector3f& up) {
  if (first.empty() || second.empty()) return 0.0f;
  return rangeOverlap(heightRange(cloud, first, up), heightRange(cloud, second, up));
}

namespace {

// The island (sorted indices) holding most of `points`, if any holds one.
const std::vector<int>* islandHolding(const std::vector<std::vector<int>>& islands, const std::vector<int>& points) {
  const std::vector<int>* best = nullptr;
  std::size_t most = 0;
  for (const std::vector<int>& island : islands) {
    const std::size_t shared = intersectionSize(island, points);
    if (shared > most) {
      most = shared;
      best = &island;
    }
  }
  return best;
}

}  // namespace

void CoaxialPieceStage::run(PipelineState& state) const {
  std::size_t joined = 0;
  if (!state.up) {
    state.count("joined", joined);
    return;
  }
  const Eigen::Vector3f up = *state.up;
  const Cloud& cloud = *state.cloud;
  // Heights once per segment; axes only for segments of pairs that pass the cheaper tests.
  std::vector<std::pair<float, float>> heights(state.segments.size(), {0.0f, 0.0f});
  for (std::size_t s = 0; s < state.segments.size(); ++s) {
    if (!state.segments[s].points.empty()) heights[s] = heightRange(cloud, state.segments[s].points, up);
  }
  // Before dedup many segments are one point set cut under several planes: one fit serves them.
  std::vector<std::size_t> same_points(state.segments.size());
  for (std::size_t s = 0; s < state.segments.size(); ++s) {
    same_points[s] = s;
    for (std::size_t t = 0; t < s; ++t) {
      if (same_points[t] == t && state.segments[t].points == state.segments[s].points) {
        same_points[s] = t;
        break;
      }
    }
  }
  std::vector<std::optional<std::optional<Eigen::Vector3f>>> fitted(state.segments.size());
  const auto axisOf = [&](std::size_t s) -> const std::optional<Eigen::Vector3f>& {
    auto& axis = fitted[same_points[s]];
    if (!axis) axis = revolutionAxis(cloud, state.segments[s].points, up, axes_, params_.min_axis_share);
    return *axis;
  };
  std::vector<CandidateSegment> unions;
  for (std::size_t a = 0; a < state.segments.size(); ++a) {
    for (std::size_t b = a + 1; b < state.segments.size(); ++b) {
      const CandidateSegment& first = state.segments[a];
      const CandidateSegment& second = state.segments[b];
      // Pieces seen apart share no point (sharing some, they are two cuts of one region, or two
      // objects; learn41: a bowl turned over on a tin, and a cut holding both).
      if (overlapOfSmaller(first.points, second.points) > 0.0f) continue;
      // A bowl's walls span the same heights; a bowl turned over on a tin stands above it.
      if (rangeOverlap(heights[a], heights[b]) < params_.min_height_overlap) continue;
      const std::optional<Eigen::Vector3f>& first_axis = axisOf(a);
      if (!first_axis) continue;
      const std::optional<Eigen::Vector3f>& second_axis = axisOf(b);
      if (!second_axis) continue;
      Eigen::Vector3f apart = *first_axis - *second_axis;
      apart -= apart.dot(up) * up;
      if (apart.norm() > params_.max_axis_distance) continue;
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
      if (passesFilterAfterOffsetFit(joint, *state.evidence, filter_)) unions.push_back(std::move(joint));
    }
  }
  // A handle: a piece of the body's island beside it (handle_pieces.h).
  std::size_t handles = 0;
  if (params_.max_handle_share > 0.0f) {
    for (std::size_t s = 0; s < state.segments.size(); ++s) {
      if (same_points[s] != s || !passesFilter(state.segments[s], filter_)) continue;
      const std::optional<Eigen::Vector3f>& axis = axisOf(s);
      if (!axis) continue;
      const std::vector<int>* island = islandHolding(state.islands, state.segments[s].points);
      if (island == nullptr) continue;
      for (CandidateSegment& joint :
           bodiesWithHandles(state.segments[s], *axis, *island, *state.evidence, up, params_.max_handle_share)) {
        if (passesFilterAfterOffsetFit(joint, *state.evidence, filter_)) {
          unions.push_back(std::move(joint));
          ++handles;
        }
      }
    }
  }
  state.count("handles", handles);
  joined = unions.size() - handles;
  for (CandidateSegment& joint : unions) state.segments.push_back(std::move(joint));
  state.count("joined", joined);
}

}  // namespace symmetry_segmentation
