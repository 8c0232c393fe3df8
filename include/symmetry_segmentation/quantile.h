#pragma once
// Order statistics of a list of values, for extents that a few stray points must not widen.
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace symmetry_segmentation {

/// The value at `quantile` (0..1) of `values` (reordered; nearest rank below). Not empty.
inline float quantileOf(std::vector<float>& values, float quantile) {
  const auto k = static_cast<std::ptrdiff_t>(quantile * static_cast<float>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[static_cast<std::size_t>(k)];
}

/// The `trim` and 1 - `trim` quantiles of `values` (reordered). Not empty.
inline std::pair<float, float> trimmedRange(std::vector<float>& values, float trim) {
  const float low = quantileOf(values, trim);
  return {low, quantileOf(values, 1.0f - trim)};
}

/// The span between the `trim` and 1 - `trim` quantiles of `values` (reordered). Not empty.
inline float trimmedSpan(std::vector<float>& values, float trim) {
  const auto [low, high] = trimmedRange(values, trim);
  return high - low;
}

}  // namespace symmetry_segmentation
