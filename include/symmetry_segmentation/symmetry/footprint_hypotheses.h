#pragma once
// Stage 7, footprints (our addition): planes for an object no other hypothesis reached; the cut
// and refine stages after it form a second round for these planes alone.
//
// Curve pairs and single surfaces propose the planes of most objects; an object seen from one
// side only, with few normal edges and no surface of revolution, can get none that its cut
// takes, and is then missed outright; an L-shaped block whose face planes came out a few degrees
// off is found in pieces. When it stands apart (an island of points, see island_segments.h) and
// no candidate passing the filter covers it, the gravity prior still gives two good guesses: the
// vertical planes through the middle of its footprint along the footprint's principal axes (a
// box, an L or U shape, a mug seen from its handle's side). The cut, refinement and filter judge
// them as any other hypothesis.
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
