#pragma once
// Stage 11, filter (paper eq. 13-14): the candidates that look like whole symmetric objects
// become the segments - their reflections explained (occlusion score above s_occl: few land in
// free space) and their boundary at creases (smoothness score below s_smooth: few smooth links
// cut). The same test judges every segment the later stages make.
//
// A candidate that fails only on occlusion is first scored again with its plane moved along its
// normal by a few millimetres (plane_offset_search): refine's ICP aligns the faces, which leaves
// the offset loose when no face crosses the plane (a box seen face-on), and on a small object
// the rim's reflections then land just beyond the far rim, in free space (OSD learn14: a 9 cm
// box, plane 9 mm off, occlusion 0.915). The offset that explains most reflections stays.

#include <optional>
#include <vector>

#include "symmetry_segmentation/segmentation_result.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {
class SceneEvidence;
}

namespace symmetry_segmentation {

struct CandidateSegment {
  std::vector<int> points;  ///< Working-cloud indices, sorted.
  SymmetryPlane plane;
  SegmentScores scores;
  std::vector<int> extra_input_points;  ///< Input points beyond its voxels' (object bottoms), sorted.
  /// Points of its unseen side, its reflections (and turned copies) into unobserved space (stage
  /// completion).
  std::optional<std::vector<Eigen::Vector3f>> completion;
  /// Its sides carried down through unobserved space to the support (stage completion).
  std::vector<Eigen::Vector3f> grounded;
  /// It stands on the support, on no other segment: its completed box reaches down to the
  /// support (stage completion).
  bool rests_on_support = false;
};

/// Occlusion score above s_occl, smoothness score below s_smooth, at least min_segment_points.
bool passesFilter(const CandidateSegment& segment, const SymmetryFilterParams& params);

/// `candidate` with its plane moved along its normal to the offset within +-`reach` (2 mm steps)
/// whose occlusion score is highest, and that score (its points stay). Unchanged when no offset
/// scores higher.
void fitPlaneOffset(CandidateSegment& candidate, const SceneEvidence& evidence, float reach);

/// passesFilter, after fitPlaneOffset (reach plane_offset_search) when only s_occl fails: a
/// candidate a later stage makes (an island, a union of pieces) gets the chance the filter
/// gives the cuts' candidates.
bool passesFilterAfterOffsetFit(CandidateSegment& candidate, const SceneEvidence& evidence,
                                const SymmetryFilterParams& params);

/// The stage: the segments become the candidates that pass the filter.
class FilterStage : public Stage {
 public:
  explicit FilterStage(const SymmetryFilterParams& params) : params_(params) {}
  void run(PipelineState& state) const override;

 private:
  SymmetryFilterParams params_;
};

}  // namespace symmetry_segmentation
