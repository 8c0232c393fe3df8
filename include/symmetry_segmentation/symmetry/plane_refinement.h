#pragma once
// Stage 5, refine (paper): a better plane for each candidate, then its cut again. The
// segment's reflection is aligned back onto the segment with point-to-plane ICP constrained to a
// reflection (one-to-one correspondences); a plane that moved is cut and scored anew. Hypotheses
// from curves are a few degrees off; the refined plane explains more of the object.

#include <vector>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// The refined plane, or `plane` itself when the segment is too small or ICP fails.
SymmetryPlane refinePlane(const Cloud& cloud, const std::vector<int>& segment, const SymmetryPlane& plane,
                          const SymmetryRefinementParams& refinement);

/// The stage: refines every candidate not refined yet (candidates under the filter's
/// min_segment_points keep their plane).
class RefineStage : public Stage {
 public:
  RefineStage(const SymmetryRefinementParams& params, const SymmetryFilterParams& filter)
      : params_(params), filter_(filter) {}
  void run(PipelineState& state) const override;

 private:
  SymmetryRefinementParams params_;
  SymmetryFilterParams filter_;
};

}  // namespace symmetry_segmentation
