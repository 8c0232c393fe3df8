// Stage 10, filter: the candidates that pass the paper's score thresholds (see the header).
#include "symmetry_segmentation/symmetry/segment_filter.h"

#include "symmetry_segmentation/symmetry/pipeline_state.h"

namespace symmetry_segmentation {

bool passesFilter(const CandidateSegment& segment, const SymmetryFilterParams& params) {
  return static_cast<int>(segment.points.size()) >= params.min_segment_points &&
         segment.scores.occlusion > params.s_occl && segment.scores.smoothness < params.s_smooth;
}

void FilterStage::run(PipelineState& state) const {
  std::size_t non_empty = 0;
  state.segments.clear();
  for (const CandidateSegment& candidate : state.candidates) {
    if (static_cast<int>(candidate.points.size()) >= params_.min_segment_points) ++non_empty;
    // Copies: later stages still read the candidates (colour seams try their planes).
    if (passesFilter(candidate, params_)) state.segments.push_back(candidate);
  }
  state.count("candidates", non_empty);
  state.count("kept", state.segments.size());
}

}  // namespace symmetry_segmentation
