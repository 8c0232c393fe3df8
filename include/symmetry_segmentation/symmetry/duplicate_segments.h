#pragma once
// Stage 18, dedup (paper): one segment per object. Many hypotheses find the same
// object (curve pairs and surfaces propose its planes several times over, islands add it whole);
// of segments that overlap by most of the smaller one, the one with the cleanest boundary stays.

#include <vector>

#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// Intersection over the smaller of two sorted index sets (0 when either is empty).
float overlapOfSmaller(const std::vector<int>& a, const std::vector<int>& b);

/// Among segments overlapping by more than `params.max_overlap` (of the smaller one), keeps the
/// one with the cleanest boundary (lowest smoothness score, then the larger, then the one whose plane
/// explains more reflections - its occlusion score -, then the earlier).
std::vector<CandidateSegment> removeDuplicates(std::vector<CandidateSegment> segments, const DuplicateParams& params);

/// The stage: the segments without duplicates.
class DuplicateStage : public Stage {
 public:
  explicit DuplicateStage(const DuplicateParams& params) : params_(params) {}
  void run(PipelineState& state) const override;

 private:
  DuplicateParams params_;
};

}  // namespace symmetry_segmentation
