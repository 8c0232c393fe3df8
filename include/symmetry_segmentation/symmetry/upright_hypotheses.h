#pragma once
// Stage 3, upright (our addition): vertical symmetry planes proposed from single smooth surfaces,
// under the gravity prior of a tabletop (objects stand on the table, so most of their symmetry
// planes are vertical). Curve pairs need two normal edges; a bottle or a can offers almost none,
// so it is proposed from its surfaces instead:
//  - a curved surface whose normals meet a common vertical axis (surface of revolution): the
//    vertical plane through that axis whose orientation the scene's evidence contradicts least
//    over the column around the axis (the mug's plane goes through its handle);
//  - a vertical flat face: the vertical plane bisecting it;
//  - a horizontal flat face: the vertical planes along its two principal axes.
// Needs the table; without one it proposes nothing. The cut, refinement and filter judge these
// as any other hypothesis.

#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// Planes proposed from each merged surface of `evidence.cloud()` (labels from
/// mergedSegmentLabels; 0 = none). `up` is the unit normal of the supporting plane. Each
/// hypothesis' support is its surface's size; planes through an axis are anchored on the axis'
/// surface. Deterministic, ordered by surface label.
std::vector<SymmetryHypothesis> uprightHypotheses(const SceneEvidence& evidence, const std::vector<int>& labels,
                                                  const Eigen::Vector3f& up, const UprightHypothesisParams& params);

/// `extra` hypotheses appended to `base` unless near-equal (angle and offset) to one already there.
void appendDistinctHypotheses(std::vector<SymmetryHypothesis>& base, const std::vector<SymmetryHypothesis>& extra,
                              float max_angle_deg, float max_distance);

/// The stage: upright planes not near-equal to a hypothesis already there, appended.
class UprightStage : public Stage {
 public:
  explicit UprightStage(const UprightHypothesisParams& params) : params_(params) {}
  void run(PipelineState& state) const override;

 private:
  UprightHypothesisParams params_;
};

}  // namespace symmetry_segmentation
