// Stage-5 scores of a segment (paper eq. 13-14, as we read them):
//   occlusion  = |{p in S : reflection of p does not land in observed free space}| / |S|
//                (it lands on a scene point within dmax, in unknown/occupied space or below the table)
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
  int explained = 0;
  int broken_links = 0;
  for (int i : segment) {
    if (data_term.evaluate(i, plane).landing != ReflectionLanding::Free) ++explained;
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
  result.occlusion = static_cast<float>(explained) / size;
  result.smoothness = static_cast<float>(broken_links) / size;
  return result;
}

}  // namespace symmetry_segmentation
