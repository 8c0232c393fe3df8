#pragma once
// The neighbour links inside one segment, for the stages that split or trim segments.
#include <cstddef>
#include <vector>

#include "disjoint_sets.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"

namespace symmetry_segmentation {

// Calls visit(j, k) once for every link between positions j < k of `points` (sorted working-cloud
// indices); `neighbours` lists each link from both ends.
template <typename Visit>
void forEachLink(const std::vector<int>& points, const std::vector<std::vector<int>>& neighbours, Visit visit) {
  for (std::size_t j = 0; j < points.size(); ++j) {
    const int p = points[j];
    if (p < 0 || static_cast<std::size_t>(p) >= neighbours.size()) continue;
    for (int q : neighbours[p]) {
      if (q <= p) continue;
      const int k = positionIn(points, q);
      if (k >= 0) visit(static_cast<int>(j), k);
    }
  }
}

// The linked pieces of `points` (sorted working-cloud indices): the piece of each position,
// pieces numbered in the order of their first position; `count` is set to how many there are.
inline std::vector<int> linkedPieceOf(const std::vector<int>& points, const std::vector<std::vector<int>>& neighbours,
                                      int& count) {
  DisjointSets sets(points.size());
  forEachLink(points, neighbours, [&](int j, int k) { sets.unite(j, k); });
  std::vector<int> number(points.size(), -1);  // by root
  std::vector<int> piece(points.size());
  count = 0;
  for (std::size_t j = 0; j < points.size(); ++j) {
    const int root = sets.find(static_cast<int>(j));
    if (number[root] < 0) number[root] = count++;
    piece[j] = number[root];
  }
  return piece;
}

}  // namespace symmetry_segmentation
