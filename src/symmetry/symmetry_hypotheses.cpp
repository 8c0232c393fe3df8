// Stage 2, curve_pairs: the mean-shift modes of each curve pair's matched point pairs, then near-equal
// planes of different pairs merged, their support added up.
#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"

#include <algorithm>

#include "curve_geometry.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"

namespace symmetry_segmentation {
namespace {

}  // namespace

std::vector<SymmetryHypothesis> detectSymmetryHypotheses(const Cloud& cloud, const std::vector<Curve>& curves,
                                                         const CurvePairParams& params) {
  std::vector<CurveGeometry> geometry;
  geometry.reserve(curves.size());
  for (const Curve& curve : curves) geometry.emplace_back(cloud, curve);

  // A mode of one curve pair needs min_pair_support matches to be evidence at all. The evidence
  // for one plane is often spread over several short curves (an edge of a small box at 1 cm
  // resolution has ~10 points), so min_plane_support applies to the merged support instead.
  const int pair_minimum = std::min(params.min_pair_support, params.min_plane_support);
  std::vector<PlaneSample> pair_planes;
  for (std::size_t a = 0; a < geometry.size(); ++a) {
    for (std::size_t b = a; b < geometry.size(); ++b) {
      const auto samples = matchCurveGeometry(geometry[a], geometry[b], a == b, params);
      if (static_cast<int>(samples.size()) < pair_minimum) continue;
      // A pair may hold several planes (a long curve runs around a box top), so keep every mode.
      for (const auto& mode : meanShiftPlanes(samples, params.mean_shift_angle_deg, params.mean_shift_distance)) {
        if (mode.support < pair_minimum) break;  // Strongest first.
        PlaneSample plane;
        plane.plane = mode.plane;
        plane.weight = static_cast<float>(mode.support);
        pair_planes.push_back(plane);
      }
    }
  }

  auto merged = meanShiftPlanes(pair_planes, params.merge_plane_angle_deg, params.merge_plane_distance);
  const auto weak = std::find_if(merged.begin(), merged.end(), [&](const SymmetryHypothesis& h) {
    return h.support < params.min_plane_support;
  });
  merged.erase(weak, merged.end());
  if (params.max_hypotheses >= 0 && static_cast<int>(merged.size()) > params.max_hypotheses) {
    merged.resize(params.max_hypotheses);
  }
  return merged;
}

void CurvePairStage::run(PipelineState& state) const {
  const std::vector<SymmetryHypothesis> planes = detectSymmetryHypotheses(*state.cloud, state.curves, params_);
  state.hypotheses.insert(state.hypotheses.end(), planes.begin(), planes.end());
  state.count("hypotheses", planes.size());
}

}  // namespace symmetry_segmentation
