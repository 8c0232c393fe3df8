// Stage 11, filter: the candidates that pass the paper's score thresholds (see the header).
#include "symmetry_segmentation/symmetry/segment_filter.h"

#include <algorithm>
#include <cmath>

#include "symmetry_segmentation/parallel_for.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/scene_evidence.h"

namespace symmetry_segmentation {

bool passesFilter(const CandidateSegment& segment, const SymmetryFilterParams& params) {
  return static_cast<int>(segment.points.size()) >= params.min_segment_points &&
         segment.scores.occlusion > params.s_occl && segment.scores.smoothness < params.s_smooth;
}

void fitPlaneOffset(CandidateSegment& candidate, const SceneEvidence& evidence, float reach) {
  constexpr float kStep = 0.002f;  // fixed: a fifth of a working voxel
  const int steps = static_cast<int>(std::floor(reach / kStep + 1e-4f));
  const SymmetryPlane start = candidate.plane;
  for (int k = -steps; k <= steps; ++k) {
    if (k == 0) continue;
    SymmetryPlane moved = start;
    moved.distance += static_cast<float>(k) * kStep;
    const SegmentScores scores = evidence.scores(candidate.points, moved);
    if (scores.occlusion > candidate.scores.occlusion) {
      candidate.plane = moved;
      candidate.scores = scores;
    }
  }
}

bool passesFilterAfterOffsetFit(CandidateSegment& candidate, const SceneEvidence& evidence,
                                const SymmetryFilterParams& params) {
  if (passesFilter(candidate, params)) return true;
  if (!(params.plane_offset_search > 0.0f) || static_cast<int>(candidate.points.size()) < params.min_segment_points ||
      !(candidate.scores.smoothness < params.s_smooth)) {
    return false;
  }
  fitPlaneOffset(candidate, evidence, params.plane_offset_search);
  return passesFilter(candidate, params);
}

void FilterStage::run(PipelineState& state) const {
  std::size_t non_empty = 0;
  state.segments.clear();
  std::size_t refitted = 0;
  if (params_.plane_offset_search > 0.0f) {
    std::vector<char> passed(state.candidates.size(), 0);
    parallelFor(state.candidates.size(), state.threads, [&](std::size_t i) {
      CandidateSegment& candidate = state.candidates[i];
      if (passesFilter(candidate, params_)) return;
      passed[i] = passesFilterAfterOffsetFit(candidate, *state.evidence, params_);
    });
    refitted = static_cast<std::size_t>(std::count(passed.begin(), passed.end(), 1));
  }
  for (const CandidateSegment& candidate : state.candidates) {
    if (static_cast<int>(candidate.points.size()) >= params_.min_segment_points) ++non_empty;
    // Copies: later stages still read the candidates (colour seams try their planes).
    if (passesFilter(candidate, params_)) state.segments.push_back(candidate);
  }
  state.count("candidates", non_empty);
  state.count("kept", state.segments.size());
  state.count("kept_after_offset_fit", refitted);
}

}  // namespace symmetry_segmentation
