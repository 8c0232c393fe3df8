// Stage 18, dedup: one segment per object (see the header).
#include "symmetry_segmentation/symmetry/duplicate_segments.h"

#include <algorithm>
#include <numeric>

#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"

namespace symmetry_segmentation {

float overlapOfSmaller(const std::vector<int>& a, const std::vector<int>& b) {
  if (a.empty() || b.empty()) return 0.0f;
  const std::size_t common = intersectionSize(a, b);
  return static_cast<float>(common) / static_cast<float>(std::min(a.size(), b.size()));
}

std::vector<CandidateSegment> removeDuplicates(std::vector<CandidateSegment> segments, const DuplicateParams& params) {
  std::vector<std::size_t> order(segments.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto& x = segments[a];
    const auto& y = segments[b];
    if (x.scores.smoothness != y.scores.smoothness) return x.scores.smoothness < y.scores.smoothness;
    if (x.points.size() != y.points.size()) return x.points.size() > y.points.size();
    // The same points under several planes: the plane that explains most reflections.
    return x.scores.occlusion > y.scores.occlusion;
  });
  std::vector<CandidateSegment> kept;
  for (std::size_t index : order) {
    const bool duplicate = std::any_of(kept.begin(), kept.end(), [&](const CandidateSegment& k) {
      return overlapOfSmaller(k.points, segments[index].points) > params.max_overlap;
    });
    if (!duplicate) kept.push_back(std::move(segments[index]));
  }
  return kept;
}

void DuplicateStage::run(PipelineState& state) const {
  state.segments = removeDuplicates(std::move(state.segments), params_);
  state.count("kept", state.segments.size());
}

}  // namespace symmetry_segmentation
