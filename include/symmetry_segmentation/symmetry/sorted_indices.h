#pragma once
// Set operations on sorted point-index lists (segments keep their indices sorted).
#include <algorithm>
#include <cstddef>
#include <iterator>
#include <vector>

namespace symmetry_segmentation {

inline std::size_t intersectionSize(const std::vector<int>& a, const std::vector<int>& b) {
  std::size_t count = 0;
  for (auto i = a.begin(), j = b.begin(); i != a.end() && j != b.end();) {
    if (*i < *j) {
      ++i;
    } else if (*j < *i) {
      ++j;
    } else {
      ++count;
      ++i;
      ++j;
    }
  }
  return count;
}

inline std::vector<int> intersection(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> common;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
  return common;
}

inline std::vector<int> difference(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> rest;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(rest));
  return rest;
}

inline std::vector<int> setUnion(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> all;
  all.reserve(a.size() + b.size());
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(all));
  return all;
}

/// Position of `value` in `sorted`, or -1 if it is not there.
inline int positionIn(const std::vector<int>& sorted, int value) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), value);
  return it != sorted.end() && *it == value ? static_cast<int>(it - sorted.begin()) : -1;
}

inline bool contains(const std::vector<int>& sorted, int value) {
  return std::binary_search(sorted.begin(), sorted.end(), value);
}

}  // namespace symmetry_segmentation
