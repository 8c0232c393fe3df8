// Stage 12, island_segments: islands that one plane explains (see the header for why).
#include "symmetry_segmentation/symmetry/island_segments.h"

#include <algorithm>

#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"

namespace symmetry_segmentation {

std::vector<CandidateSegment> explainedIslands(const std::vector<std::vector<int>>& islands,
                                               const std::vector<CandidateSegment>& segments,
                                               const std::vector<CandidateSegment>& reported,
                                               const SceneEvidence& evidence, const SymmetryFilterParams& filter,
                                               const IslandSegmentParams& params) {
  std::vector<CandidateSegment> result;
  for (const std::vector<int>& island : islands) {
    CandidateSegment best;
    bool found = false;
    for (const CandidateSegment& segment : segments) {
      if (segment.points.empty()) continue;
      // A segment lends its plane when it lies on the island and covers a good share of it: a
      // piece of the object, not a detail of a large island of many objects (whose scoring under
      // every plane would cost more than the cuts).
      const std::size_t common = intersectionSize(segment.points, island);
      if (common < params.min_share_on_island * segment.points.size() ||
          common < params.min_share_of_island * island.size()) {
        continue;
      }
      CandidateSegment candidate;
      candidate.points = island;
      candidate.plane = segment.plane;
      candidate.scores = evidence.scores(island, segment.plane);
      if (!found || candidate.scores.occlusion > best.scores.occlusion) {
        best = std::move(candidate);
        found = true;
      }
    }
    if (!found) continue;
    if (passesFilterAfterOffsetFit(best, evidence, filter)) {
      result.push_back(std::move(best));
      continue;
    }
    const bool covered = std::any_of(reported.begin(), reported.end(), [&](const CandidateSegment& segment) {
      return 2 * intersectionSize(segment.points, island) >= island.size();
    });
    SymmetryFilterParams alone = filter;
    alone.s_occl = 1.0f - params.alone_free_factor * (1.0f - filter.s_occl);
    if (!covered && passesFilter(best, alone)) result.push_back(std::move(best));
  }
  return result;
}

void IslandSegmentStage::run(PipelineState& state) const {
  std::vector<CandidateSegment> explained =
      explainedIslands(state.islands, state.candidates, state.segments, *state.evidence, filter_, params_);
  state.count("added", explained.size());
  for (CandidateSegment& island : explained) state.segments.push_back(std::move(island));
}

}  // namespace symmetry_segmentation
