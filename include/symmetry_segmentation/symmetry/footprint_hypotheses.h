#pragma once
// Stage 7, footprints (our addition): an island (islands.h) that no candidate passing the filter
// covers - an object seen from one side, with few edges and no surface of revolution, or one found
// in pieces because its planes came out a few degrees off - gets the two vertical planes through
// the middle of its footprint along the footprint's principal axes. The cut and refine listed
// after it are a second round for these planes alone.
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"

namespace symmetry_segmentation {

/// The two vertical planes (for the table's unit normal `up`) through the middle of the
/// footprint of `group` (working-cloud indices) along its principal axes, anchored on the group.
/// Empty for fewer than three points or a footprint longer than `max_extent` (m).
std::vector<SymmetryHypothesis> footprintHypotheses(const Cloud& cloud, const std::vector<int>& group,
                                                    const Eigen::Vector3f& up, float max_extent);

/// The groups (sorted indices) of which no segment of `segments` covers at least `min_share`.
std::vector<std::vector<int>> groupsNoSegmentCovers(const std::vector<std::vector<int>>& groups,
                                                    const std::vector<CandidateSegment>& segments, float min_share);

/// The stage: footprint planes of every island no candidate passing the filter covers, appended
/// to the hypotheses (nothing without a table).
class FootprintStage : public Stage {
 public:
  FootprintStage(const FootprintParams& params, const SymmetryFilterParams& filter) : params_(params), filter_(filter) {}
  void run(PipelineState& state) const override;

 private:
  FootprintParams params_;
  SymmetryFilterParams filter_;
};

}  // namespace symmetry_segmentation
