#pragma once
// Post-processing of a cut: a cut can return unrelated foreground patches; keep the connected
// one with the most symmetry support.

#include <utility>
#include <vector>

namespace symmetry_segmentation {

/// Connected components of the `foreground` points over `neighbours` (adjacency lists) and
/// `links` (extra undirected pairs, e.g. symmetric counterparts); returns the sorted points of the
/// component with the largest sum of `support`, or nothing when no component has positive support.
/// With `anchor` points given, the positively supported component holding most of them wins
/// (support breaks ties; none holding any: the best-supported one).
std::vector<int> strongestForegroundComponent(const std::vector<char>& foreground,
                                              const std::vector<std::vector<int>>& neighbours,
                                              const std::vector<std::pair<int, int>>& links,
                                              const std::vector<float>& support,
                                              const std::vector<int>& anchor = {});

}  // namespace symmetry_segmentation
