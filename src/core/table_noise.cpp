#include "symmetry_segmentation/table_noise.h"

#include <algorithm>
#include <cmath>

#include "symmetry_segmentation/quantile.h"

namespace symmetry_segmentation {
namespace {

constexpr float kNoiseSigmas = 3.0f;
constexpr float kHalfSpreadToSigma = 1.4826f;
constexpr int kNearReach = 1;

}  // namespace

std::vector<bool> tableNoisePixels(std::uint32_t width, std::uint32_t height, const std::vector<float>& heights,
                                   float margin, int reach) {
  const int w = static_cast<int>(width), h = static_cast<int>(height);
  std::vector<bool> noise(heights.size(), false);
  if (reach <= 0 || heights.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) return noise;
  const std::size_t window = static_cast<std::size_t>(2 * reach + 1) * static_cast<std::size_t>(2 * reach + 1);
  std::vector<float> values;
  values.reserve(window);
  // The finite heights of the square of `radius` pixels around (x, y).
  auto gather = [&](int x, int y, int radius, std::vector<float>& out) {
    out.clear();
    for (int v = std::max(0, y - radius); v <= std::min(h - 1, y + radius); ++v) {
      for (int u = std::max(0, x - radius); u <= std::min(w - 1, x + radius); ++u) {
        const float value = heights[static_cast<std::size_t>(v) * w + u];
        if (std::isfinite(value)) out.push_back(value);
      }
    }
  };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float own = heights[static_cast<std::size_t>(y) * w + x];
      if (!(own > margin)) continue;  // NaN or already within the margin
      // Its nearest neighbours first: an object's edge against the table has half its window on
      // the table, but the pixels right around it on the object.
      gather(x, y, kNearReach, values);
      if (values.empty() || quantileOf(values, 0.5f) > margin) continue;
      gather(x, y, reach, values);
      if (2 * values.size() < window) continue;
      const float median = quantileOf(values, 0.5f);
      if (median > margin) continue;
      // The spread below the median: what stands out above the table (a handle before it) must
      // not widen the table's noise. For a Gaussian, median - lower quartile is 0.6745 sigma.
      const float sigma = kHalfSpreadToSigma * (median - quantileOf(values, 0.25f));
      // Where the margin covers the noise the margin decides: the pixel is a thing on the table.
      if (kNoiseSigmas * sigma <= margin) continue;
      noise[static_cast<std::size_t>(y) * w + x] = own - median <= kNoiseSigmas * sigma;
    }
  }
  return noise;
}

}  // namespace symmetry_segmentation
