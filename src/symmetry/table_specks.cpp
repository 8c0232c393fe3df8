#include "symmetry_segmentation/symmetry/table_specks.h"

#include <algorithm>
#include <map>

#include "disjoint_sets.h"
#include "segment_links.h"

namespace symmetry_segmentation {

std::vector<int> withoutTableSpecks(const Cloud& cloud, const std::vector<std::vector<int>>& neighbours,
                                    const std::vector<int>& segment, const TableTop& table,
                                    float max_link, float max_height,
                                    const std::function<bool(const std::vector<int>&)>& keep_low_piece) {
  if (segment.empty() || !(table.plane.head<3>().norm() > 0.0f)) return segment;
  const auto outside = [&](int i) {
    return i < 0 || static_cast<std::size_t>(i) >= cloud.size() || static_cast<std::size_t>(i) >= neighbours.size();
  };
  if (std::any_of(segment.begin(), segment.end(), outside)) return segment;

  const int size = static_cast<int>(segment.size());
  DisjointSets pieces(segment.size());
  const float max_link_squared = max_link * max_link;
  forEachLink(segment, neighbours, [&](int j, int k) {
    const float squared = (cloud[segment[j]].getVector3fMap() - cloud[segment[k]].getVector3fMap()).squaredNorm();
    if (squared < max_link_squared) pieces.unite(j, k);
  });
  std::vector<char> piece_high(segment.size(), 0);
  bool any_high = false;
  for (int k = 0; k < size; ++k) {
    const float height = table.height(cloud[segment[k]].getVector3fMap());
    if (height > max_height) {
      piece_high[pieces.find(k)] = 1;
      any_high = true;
    }
  }
  if (!any_high) return segment;
  std::map<int, std::vector<int>> low_pieces;  // by root, each sorted as the segment is
  for (int k = 0; k < size; ++k) {
    if (!piece_high[pieces.find(k)]) low_pieces[pieces.find(k)].push_back(segment[k]);
  }
  std::vector<char> keep_piece(segment.size(), 0);
  for (const auto& [root, points] : low_pieces) keep_piece[root] = keep_low_piece && keep_low_piece(points);
  std::vector<int> kept;
  kept.reserve(segment.size());
  for (int k = 0; k < size; ++k) {
    const int root = pieces.find(k);
    if (piece_high[root] || keep_piece[root]) kept.push_back(segment[k]);
  }
  return kept;
}

}  // namespace symmetry_segmentation
