#pragma once
// Stage 12, island_segments (our addition): an island (islands.h) that one of the found planes
// explains whole (it passes the filter) is added as a segment, so an object whose cut came out in
// pieces - its plane a few degrees off, or one arm's plane (an L-shaped block, a mug and its
// handle) - can still be reported whole; deduplication then prefers it to its pieces. An island
// no segment covers half of needs less: its best plane a little off (an L-shaped block whose
// only plane is its horizontal mid-plane, a fused scene's noise), it is an object nothing else
// accounts for, set apart from everything by the islands' gap; only a plane that sends many times
// the filter's share into free space says it is none (a wall's scrap, a shadow's speckle). The
// share scales with the filter's s_occl, so a stricter filter is stricter here too.
#include <vector>

#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// For each island: the plane among `segments`' planes (of segments lying mostly on the island
/// and covering a good share of it) under which the island scores best; the island with that
/// plane when it passes `filter` (after the filter's plane offset search), or when none of
/// `reported` covers half of it and it passes `filter` with params.alone_free_factor times the
/// filter's share of reflections into free space (1 - s_occl).
std::vector<CandidateSegment> explainedIslands(const std::vector<std::vector<int>>& islands,
                                               const std::vector<CandidateSegment>& segments,
                                               const std::vector<CandidateSegment>& reported,
                                               const SceneEvidence& evidence, const SymmetryFilterParams& filter,
                                               const IslandSegmentParams& params);

/// The stage: the explained islands (planes from every candidate, coverage by the segments)
/// appended to the segments.
class IslandSegmentStage : public Stage {
 public:
  IslandSegmentStage(const IslandSegmentParams& params, const SymmetryFilterParams& filter)
      : params_(params), filter_(filter) {}
  void run(PipelineState& state) const override;

 private:
  IslandSegmentParams params_;
  SymmetryFilterParams filter_;
};

}  // namespace symmetry_segmentation
