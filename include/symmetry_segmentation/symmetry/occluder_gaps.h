#pragma once
// Stage 9, occluder_gaps (our addition): an object behind a narrower one is seen as two pieces, one
// either side of the occluder, and each piece alone is often symmetric enough to pass as an
// object. Its own symmetry plane lies in the hidden gap, where no curve pair proposes it (OSD's
// occluded frames: 0.63 -> 0.88). For two passing candidates that do not touch, lie apart along
// the line between them and have unobserved space (not free) between them, this cuts with the
// plane halfway between their outer ends, anchored on both - and with the plane turned about the
// up direction in steps (the line between the pieces is askew when they show unequal shares of
// the object's width: OSD stacked 0.79 -> 0.87, occluded 0.88 -> 0.97) - and keeps each cut as a
// candidate that takes both pieces; the refine listed after it refines it, dedup then prefers it to the
// pieces (larger at equal smoothness). Two objects seen through a gap are never joined: the gap
// is free (mirror_twins splits those). Nor are two pieces with no colours in common, in a cloud
// with colour: two pieces of one object show its colours, print included.
#include <vector>

#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// The share of `points` (working-cloud indices) whose colour lies within `max_difference`
/// (CIELAB, lightness at half weight) of a colour of `other` (at most 256 of its points, evenly
/// picked). 0 when either is empty.
float sharedColorShare(const Cloud& cloud, const std::vector<int>& points, const std::vector<int>& other,
                       float max_difference);

/// The plane halfway between the outer ends of `first` and `second` (working-cloud indices)
/// along the line between their centroids, anchored on both, when they lie apart along that line
/// by at least `params.min_gap`, span at most `params.max_span` together, and the middle of the
/// gap is not free in `occupancy`. Empty otherwise.
std::vector<SymmetryHypothesis> occluderGapHypothesis(const Cloud& cloud, const std::vector<int>& first,
                                                      const std::vector<int>& second, const OccupancyMap& occupancy,
                                                      const OccluderGapParams& params);

/// The stage: per pair of distinct passing candidates (overlapping by at most dedup's
/// max_overlap: more is one piece cut by several planes) with a hidden gap between them, the
/// cuts of their plane and of it turned about the table's up by multiples of turn_step_deg up to
/// max_turn_deg, each appended with its hypothesis when it takes both (candidates stay aligned
/// with hypotheses, so it runs after a cut, never between a hypothesis source and its cut).
class OccluderGapStage : public Stage {
 public:
  OccluderGapStage(const OccluderGapParams& params, const SymmetryFilterParams& filter, const DuplicateParams& dedup)
      : params_(params), filter_(filter), dedup_(dedup) {}
  void run(PipelineState& state) const override;

 private:
  OccluderGapParams params_;
  SymmetryFilterParams filter_;
  DuplicateParams dedup_;
};

}  // namespace symmetry_segmentation
