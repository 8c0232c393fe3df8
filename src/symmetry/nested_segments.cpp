// Optional stage nested: foreign objects taken out of a larger segment (see the header for why).
#include "symmetry_segmentation/symmetry/nested_segments.h"

#include <algorithm>
#include <numeric>

#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"

namespace symmetry_segmentation {

std::vector<std::size_t> removeForeignParts(std::vector<CandidateSegment>& segments, const SceneEvidence& evidence,
                                            int min_points, const NestedSegmentParams& params) {
  std::vector<std::size_t> order(segments.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return segments[a].points.size() > segments[b].points.size(); });
  // Nested segments as found before any removal, so the result does not depend on which large
  // segment is visited first.
  const std::vector<CandidateSegment> original = segments;
  std::vector<std::size_t> changed;
  for (std::size_t a : order) {
    const CandidateSegment& outer = original[a];
    std::vector<int> remaining = outer.points;
    for (std::size_t b = 0; b < original.size(); ++b) {
      const CandidateSegment& inner = original[b];
      if (b == a || inner.points.empty() || inner.points.size() > params.max_size_ratio * outer.points.size()) continue;
      const std::vector<int> common = intersection(outer.points, inner.points);
      if (common.size() < params.min_nested_fraction * inner.points.size()) continue;
      std::size_t explained_points = 0;
      for (int i : common) {
        explained_points += evidence.reflection(i, outer.plane).landing == ReflectionLanding::OnPoint ? 1 : 0;
      }
      if (explained_points >= params.max_explained_fraction * common.size()) continue;
      remaining = difference(remaining, inner.points);
    }
    if (remaining.size() == outer.points.size()) continue;
    if (static_cast<int>(remaining.size()) < min_points) remaining.clear();
    segments[a].points = std::move(remaining);
    changed.push_back(a);
  }
  std::sort(changed.begin(), changed.end());
  return changed;
}

void NestedStage::run(PipelineState& state) const {
  std::vector<CandidateSegment>& segments = state.segments;
  const std::vector<std::size_t> trimmed = removeForeignParts(segments, *state.evidence, filter_.min_segment_points, params_);
  for (std::size_t i : trimmed) {
    if (!segments[i].points.empty()) segments[i].scores = state.evidence->scores(segments[i].points, segments[i].plane);
  }
  segments.erase(std::remove_if(segments.begin(), segments.end(), [](const CandidateSegment& c) { return c.points.empty(); }),
                 segments.end());
  state.count("trimmed", trimmed.size());
}

}  // namespace symmetry_segmentation
