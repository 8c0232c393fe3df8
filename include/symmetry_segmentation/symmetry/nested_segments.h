#pragma once
// Optional stage nested (our addition; out of the default list since 2026-12-04: with the
// bounded neighbour graph and occluder_gaps it changed nothing on the generated sets and cost
// OSD learn 0.013 and the realistic set 0.020 - on learn35 it took a piece out of a cup; on
// kinfu it keeps one object apart from the iron, 12 segments with it, 11 without): a cut may
// take a neighbour its plane mirrors into occluded space (a can on a box, the next box of a
// row), which is no evidence against it. When that neighbour is also found alone, nested in the
// larger segment, and the larger segment's plane does not mirror it onto scene points, it is
// taken out; a part the plane explains stays.

#include <vector>

#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// Removes foreign nested segments' points from the larger segments (larger ones first; each
/// segment's points stay sorted). A point is explained when its reflection about the larger
/// segment's plane lands on a scene point (normals are not asked to match: on thin parts such as
/// a box's handle they are too noisy at 1 cm). Returns the indices of the segments that lost
/// points; those left with fewer than `min_points` points are emptied.
std::vector<std::size_t> removeForeignParts(std::vector<CandidateSegment>& segments, const SceneEvidence& evidence,
                                            int min_points, const NestedSegmentParams& params);

/// The stage: removeForeignParts; trimmed segments are scored anew (and keep their place even if
/// they would now fail the filter: losing the glued object cuts the smooth links it shared, which
/// is no fault of the rest), emptied ones are dropped.
class NestedStage : public Stage {
 public:
  NestedStage(const NestedSegmentParams& params, const SymmetryFilterParams& filter) : params_(params), filter_(filter) {}
  void run(PipelineState& state) const override;

 private:
  NestedSegmentParams params_;
  SymmetryFilterParams filter_;
};

}  // namespace symmetry_segmentation
