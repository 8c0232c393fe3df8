// Stage 7, footprints: footprint planes for islands no cut reached (see the header for why).
#include "symmetry_segmentation/symmetry/footprint_hypotheses.h"

#include <algorithm>
#include <limits>

#include <Eigen/Eigenvalues>

#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {

std::vector<SymmetryHypothesis> footprintHypotheses(const Cloud& cloud, const std::vector<int>& group,
                                                    const Eigen::Vector3f& up, float max_extent) {
  if (group.size() < 3) return {};
  // Any two horizontal directions span the footprint's plane.
  const Eigen::Vector3f u = up.unitOrthogonal();
  const Eigen::Vector3f v = up.cross(u).normalized();
  Eigen::Vector2f mean = Eigen::Vector2f::Zero();
  std::vector<Eigen::Vector2f> footprint;
  footprint.reserve(group.size());
  for (int i : group) {
    const Eigen::Vector3f p = cloud[i].getVector3fMap();
    footprint.emplace_back(u.dot(p), v.dot(p));
    mean += footprint.back();
  }
  mean /= static_cast<float>(footprint.size());
  Eigen::Matrix2f scatter = Eigen::Matrix2f::Zero();
  for (const auto& q : footprint) scatter += (q - mean) * (q - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2f> axes(scatter);

  std::vector<SymmetryHypothesis> result;
  for (int k = 1; k >= 0; --k) {  // the longer axis first
    const Eigen::Vector2f axis = axes.eigenvectors().col(k);
    // The middle of the extent, not the mean: one side is usually seen better than the other.
    float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
    for (const auto& q : footprint) {
      low = std::min(low, axis.dot(q));
      high = std::max(high, axis.dot(q));
    }
    if (high - low > max_extent) return {};  // several objects standing together, not one
    const Eigen::Vector3f normal = axis.x() * u + axis.y() * v;
    SymmetryHypothesis hypothesis;
    hypothesis.plane = verticalPlaneThrough(0.5f * (low + high) * normal, normal, up);
    hypothesis.support = static_cast<int>(group.size());
    hypothesis.anchor = group;
    result.push_back(std::move(hypothesis));
  }
  return result;
}

std::vector<std::vector<int>> groupsNoSegmentCovers(const std::vector<std::vector<int>>& groups,
                                                    const std::vector<CandidateSegment>& segments, float min_share) {
  std::vector<std::vector<int>> result;
  for (const auto& group : groups) {
    const bool covered = std::any_of(segments.begin(), segments.end(), [&](const CandidateSegment& segment) {
      return intersectionSize(segment.points, group) >= min_share * group.size();
    });
    if (!covered) result.push_back(group);
  }
  return result;
}

void FootprintStage::run(PipelineState& state) const {
  const std::size_t before = state.hypotheses.size();
  if (state.up) {
    std::vector<CandidateSegment> passing;
    for (const CandidateSegment& candidate : state.candidates) {
      if (passesFilter(candidate, filter_)) passing.push_back(candidate);
    }
    for (const auto& island : groupsNoSegmentCovers(state.islands, passing, params_.min_island_coverage)) {
      for (auto& hypothesis : footprintHypotheses(*state.cloud, island, *state.up, params_.max_extent)) {
        state.hypotheses.push_back(std::move(hypothesis));
      }
    }
  }
  state.count("hypotheses", state.hypotheses.size() - before);
}

}  // namespace symmetry_segmentation
