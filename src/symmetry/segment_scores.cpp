// The scores of a segment (paper eq. 13-14, as we read them), for the filter and every later stage:
//   occlusion  = 1 - sum_{p in S} freeCost(p) / |S|, where freeCost is the data term's cost of
//                foreground for a reflection into observed free space (0 within dmax of a surface,
//                rising to 1 at dbuf; 1 deep below the table) and 0 for any other landing. The
//                paper counts free-space landings outright; grading them the way the data term
//                does keeps a true object's score near 1 when fused-cloud noise and 1 cm voxels
//                put a few reflections just in front of the mirrored surface.
//   smoothness = |{k-NN links (p, q) : p in S, q not in S, angle(n_p, n_q) < smooth_normal_angle}| / |S|
// A true object explains its reflections (occlusion near 1) and ends at creases (smoothness near 0).
#include <algorithm>

#include "symmetry_segmentation/symmetry/reflection_data_term.h"
#include "symmetry_segmentation/symmetry/symmetric_graph_cut.h"

namespace symmetry_segmentation {

SegmentScores SymmetricGraphCut::scores(const std::vector<int>& segment, const SymmetryPlane& plane,
                                        const SymmetryFilterParams& filter) const {
  SegmentScores result;
  if (segment.empty()) return result;
  const int n = static_cast<int>(cloud_->size());
  std::vector<char> inside(n, 0);
  for (int i : segment) inside[i] = 1;

  const ReflectionDataTerm data_term = dataTermView();
  double unexplained = 0.0;
  int broken_links = 0;
  for (int i : segment) {
    const ReflectionEvidence evidence = data_term.evaluate(i, plane);
    if (evidence.landing == ReflectionLanding::Free) unexplained += evidence.cost_foreground;
    const auto& point = cloud_->points[i];
    for (int j : neighbours_[i]) {
      if (inside[j]) continue;  // each boundary link is seen once, from its inside end
      if (angleDeg(point.getNormalVector3fMap(), cloud_->points[j].getNormalVector3fMap()) <
          filter.smooth_normal_angle_deg) {
        ++broken_links;
      }
    }
  }
  const float size = static_cast<float>(segment.size());
  result.occlusion = static_cast<float>(1.0 - unexplained / size);
  result.smoothness = static_cast<float>(broken_links) / size;
  return result;
}

}  // namespace symmetry_segmentation
