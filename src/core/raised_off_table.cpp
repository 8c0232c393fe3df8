// A segment raised off the table (see the header for why).
#include "symmetry_segmentation/raised_off_table.h"

#include <algorithm>
#include <cmath>

#include "symmetry_segmentation/quantile.h"

namespace symmetry_segmentation {
namespace {
constexpr float kBaseQuantile = 0.02f;
constexpr float kTopQuantile = 0.98f;
}  // namespace

float segmentBase(std::vector<float>& heights) { return quantileOf(heights, kBaseQuantile); }

std::optional<float> raisedBase(std::vector<float>& heights, float table_margin, float min_gap) {
  heights.erase(std::remove_if(heights.begin(), heights.end(), [](float h) { return !std::isfinite(h); }), heights.end());
  if (heights.empty()) return std::nullopt;
  const float base = segmentBase(heights);
  const float top = quantileOf(heights, kTopQuantile);
  const float gap = base - table_margin;
  if (!(gap > std::max(min_gap, top - base))) return std::nullopt;
  return base;
}

}  // namespace symmetry_segmentation
