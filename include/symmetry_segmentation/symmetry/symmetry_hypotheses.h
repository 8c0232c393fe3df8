#pragma once
// Stage 2, curve_pairs (paper): every pair of curves is matched point by point
// (one-to-one, reflected tangents within 6 degrees); each matched pair's bisector is a plane
// sample, the samples of a curve pair are mean-shift clustered, and near-equal planes of
// different pairs merged. The planes are the hypotheses the graph cut tries.

#include <vector>

#include "symmetry_segmentation/segmentation_result.h"
#include "symmetry_segmentation/symmetry/normal_edge_curves.h"
#include "symmetry_segmentation/symmetry/stage.h"

namespace symmetry_segmentation {

struct SymmetryHypothesis {
  SymmetryPlane plane;  ///< Canonical sign (canonicalPlane).
  int support = 0;      ///< Matched point pairs behind it.
  /// Working-cloud points of the surface that proposed it, if known: one plane can be a symmetry
  /// of several objects, and the cut keeps the one these points are on.
  std::vector<int> anchor;
};

/// A plane sample for mean shift, with its weight.
struct PlaneSample {
  SymmetryPlane plane;
  float weight = 1.0f;
};

/// Modes of the samples under a kernel on normal angle and offset difference, strongest first.
/// Each mode carries the summed weight of the samples that converged to it. Deterministic.
std::vector<SymmetryHypothesis> meanShiftPlanes(const std::vector<PlaneSample>& samples, float angle_bandwidth_deg,
                                                float distance_bandwidth);

/// One-to-one point matches between two curves (or a curve and itself) whose reflected tangents
/// agree; returns the plane of each surviving pair.
std::vector<PlaneSample> matchCurvePair(const Cloud& cloud, const Curve& a, const Curve& b,
                                        const CurvePairParams& params);

/// Over all curve pairs: per pair the mean-shift plane, then near-equal planes merged.
/// Strongest first, at most params.max_hypotheses.
std::vector<SymmetryHypothesis> detectSymmetryHypotheses(const Cloud& cloud, const std::vector<Curve>& curves,
                                                         const CurvePairParams& params);

/// The stage: the curve-pair planes appended to the state's hypotheses.
class CurvePairStage : public Stage {
 public:
  explicit CurvePairStage(const CurvePairParams& params) : params_(params) {}
  void run(PipelineState& state) const override;

 private:
  CurvePairParams params_;
};

}  // namespace symmetry_segmentation
