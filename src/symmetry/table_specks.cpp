#include "symmetry_segmentation/symmetry/table_specks.h"

#include "disjoint_sets.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"

namespace symmetry_segmentation {

std::vector<int> withoutTableSpecks(const Cloud& cloud, const std::vector<std::vector<int>>& neighbours,
                                    const std::vector<int>& segment, const PlaneCoefficients& table_plane,
                                    float max_link, float max_height) {
  const int size = static_cast<int>(segment.size());
  const float norm = table_plane.head<3>().norm();
  if (size == 0 || !(norm > 0.0f)) return segment;
  const float max_link_squared = max_link * max_link;
  DisjointSets pieces(segment.size());
  std::vector<char> high(segment.size(), 0);
  bool any_high = false;
  for (int k = 0; k < size; ++k) {
    const int i = segment[k];
    if (i < 0 || static_cast<std::size_t>(i) >= cloud.size()) return segment;
    const Eigen::Vector3f p = cloud[i].getVector3fMap();
    high[k] = (table_plane.head<3>().dot(p) + table_plane[3]) / norm > max_height;
    any_high = any_high || high[k];
    if (static_cast<std::size_t>(i) >= neighbours.size()) continue;
    for (int j : neighbours[i]) {
      if (j <= i) continue;
      const int m = positionIn(segment, j);
      if (m >= 0 && (cloud[j].getVector3fMap() - p).squaredNorm() < max_link_squared) pieces.unite(k, m);
    }
  }
  if (!any_high) return segment;
  std::vector<char> piece_high(segment.size(), 0);
  for (int k = 0; k < size; ++k) {
    if (high[k]) piece_high[pieces.find(k)] = 1;
  }
  std::vector<int> kept;
  kept.reserve(segment.size());
  for (int k = 0; k < size; ++k) {
    if (piece_high[pieces.find(k)]) kept.push_back(segment[k]);
  }
  return kept;
}

}  // namespace symmetry_segmentation
