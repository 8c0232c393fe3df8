// Stage 9, occluder_gaps: planes across the hidden gap between two pieces of one object (see the header).
#include "symmetry_segmentation/symmetry/occluder_gaps.h"

#include <algorithm>
#include <stdexcept>

#include <pcl/common/centroid.h>

#include "symmetry_segmentation/parallel_for.h"
#include "symmetry_segmentation/quantile.h"
#include "symmetry_segmentation/symmetry/duplicate_segments.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"
#include "symmetry_segmentation/symmetry/symmetric_graph_cut.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {
namespace {

// Share of a piece's points left out at its ends: a stray point does not move an end.
constexpr float kEndTrim = 0.02f;

Eigen::Vector3f centroidOf(const Cloud& cloud, const std::vector<int>& points) {
  Eigen::Vector4f centroid;
  pcl::compute3DCentroid(cloud, points, centroid);
  return centroid.head<3>();
}

/// The kEndTrim and 1 - kEndTrim quantiles of the points' positions along `axis`.
std::pair<float, float> extentAlong(const Cloud& cloud, const std::vector<int>& points, const Eigen::Vector3f& axis) {
  std::vector<float> along;
  along.reserve(points.size());
  for (int i : points) along.push_back(axis.dot(cloud[i].getVector3fMap()));
  const float low = quantileOf(along, kEndTrim);
  return {low, quantileOf(along, 1.0f - kEndTrim)};
}

}  // namespace

std::vector<SymmetryHypothesis> occluderGapHypothesis(const Cloud& cloud, const std::vector<int>& first,
                                                      const std::vector<int>& second, const OccupancyMap& occupancy,
                                                      const OccluderGapParams& params) {
  if (first.size() < 3 || second.size() < 3) return {};
  const Eigen::Vector3f first_centre = centroidOf(cloud, first);
  const Eigen::Vector3f second_centre = centroidOf(cloud, second);
  const Eigen::Vector3f between = second_centre - first_centre;
  if (between.norm() < 1e-6f) return {};
  const Eigen::Vector3f axis = between.normalized();
  const auto [first_low, first_high] = extentAlong(cloud, first, axis);
  const auto [second_low, second_high] = extentAlong(cloud, second, axis);
  const float gap = second_low - first_high;
  if (gap < params.min_gap || second_high - first_low > params.max_span) return {};
  // The middle of the gap, at the pieces' mean position across the axis: seen through means two
  // objects; hidden (behind the occluder, or never observed) leaves it to the cut.
  const Eigen::Vector3f middle = 0.5f * (first_centre + second_centre) +
                                 axis * (0.5f * (first_high + second_low) - axis.dot(0.5f * (first_centre + second_centre)));
  if (occupancy.classify(middle) == Occupancy::Free) return {};
  SymmetryHypothesis hypothesis;
  hypothesis.plane.normal = axis;
  hypothesis.plane.distance = -0.5f * (first_low + second_high);
  hypothesis.plane = canonicalPlane(hypothesis.plane);
  hypothesis.anchor = first;
  hypothesis.anchor.insert(hypothesis.anchor.end(), second.begin(), second.end());
  std::sort(hypothesis.anchor.begin(), hypothesis.anchor.end());
  return {hypothesis};
}

void OccluderGapStage::run(PipelineState& state) const {
  // Hypotheses not cut yet would be paired with this stage's candidates (the stage list is
  // checked for this; a hand-made state may still get here).
  if (state.candidates.size() != state.hypotheses.size()) {
    throw std::logic_error("occluder_gaps: every hypothesis must be cut before it runs");
  }
  // The passing candidates, each point set once (several planes often cut the same piece).
  std::vector<const CandidateSegment*> pieces;
  for (const CandidateSegment& candidate : state.candidates) {
    if (!passesFilter(candidate, filter_)) continue;
    const bool seen = std::any_of(pieces.begin(), pieces.end(), [&](const CandidateSegment* piece) {
      return overlapOfSmaller(piece->points, candidate.points) > dedup_.max_overlap;
    });
    if (!seen) pieces.push_back(&candidate);
  }
  struct Pair {
    SymmetryHypothesis hypothesis;
    const CandidateSegment* first;
    const CandidateSegment* second;
  };
  std::vector<Pair> pairs;
  for (std::size_t a = 0; a < pieces.size(); ++a) {
    for (std::size_t b = a + 1; b < pieces.size(); ++b) {
      if (overlapOfSmaller(pieces[a]->points, pieces[b]->points) > 0.0f) continue;
      for (auto& hypothesis :
           occluderGapHypothesis(*state.cloud, pieces[a]->points, pieces[b]->points, *state.occupancy, params_)) {
        pairs.push_back({std::move(hypothesis), pieces[a], pieces[b]});
      }
    }
  }
  // Cut here rather than in a later cut stage: only a cut that joins both pieces is a candidate.
  // Any other would be one more piece for the stages that split segments into found parts.
  std::vector<CandidateSegment> cuts(pairs.size());
  parallelFor(pairs.size(), state.threads, [&](std::size_t k) {
    CandidateSegment& cut = cuts[k];
    cut.plane = pairs[k].hypothesis.plane;
    cut.points = state.graph->segment(cut.plane, pairs[k].hypothesis.anchor);
    const auto covers = [&](const CandidateSegment* piece) {
      return static_cast<float>(intersectionSize(cut.points, piece->points)) >=
             params_.min_piece_coverage * static_cast<float>(piece->points.size());
    };
    if (!covers(pairs[k].first) || !covers(pairs[k].second)) {
      cut.points.clear();
      return;
    }
    cut.scores = state.evidence->scores(cut.points, cut.plane);
  });
  // Hypotheses and candidates stay index-aligned (candidates[i] is the cut of hypotheses[i]).
  std::size_t joined = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (cuts[k].points.empty()) continue;
    state.hypotheses.push_back(std::move(pairs[k].hypothesis));
    state.candidates.push_back(std::move(cuts[k]));
    ++joined;
  }
  state.count("pairs", pairs.size());
  state.count("joined", joined);
}

}  // namespace symmetry_segmentation
