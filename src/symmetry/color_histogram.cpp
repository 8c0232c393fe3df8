// Colour overlap of two point sets (see the header for why).
#include "symmetry_segmentation/symmetry/color_histogram.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "color_lab.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"

namespace symmetry_segmentation {
namespace {

// Fine bins: one print's palette repeats exactly over its object, while two objects share a
// colour by chance, and coarse bins make chance shares large (OSD learn, touching real objects:
// 0.34-0.50 in bins of 33 and 20, 0.19-0.21 in these).
constexpr float kLightnessStep = 10.0f;
constexpr float kChromaStep = 5.0f;
constexpr int kLightnessBins = 11;  // lightness lies within 0..100
constexpr int kChromaBins = 56;     // a and b lie within about +-128

int binOf(const Eigen::Vector3f& lab) {
  const int lightness = std::clamp(static_cast<int>(lab.x() / kLightnessStep), 0, kLightnessBins - 1);
  const auto chroma = [](float value) {
    return std::clamp(static_cast<int>(std::floor(value / kChromaStep)) + kChromaBins / 2, 0, kChromaBins - 1);
  };
  return (lightness * kChromaBins + chroma(lab.y())) * kChromaBins + chroma(lab.z());
}

// The normalised histogram of the points of `part` not in `other`: (bin, share) sorted by bin.
std::vector<std::pair<int, float>> histogramApart(const Cloud& cloud, const std::vector<int>& part,
                                                  const std::vector<int>& other) {
  std::vector<int> bins;
  bins.reserve(part.size());
  for (int p : part) {
    if (!contains(other, p)) bins.push_back(binOf(toLab(cloud[p])));
  }
  std::sort(bins.begin(), bins.end());
  std::vector<std::pair<int, float>> histogram;
  const float share = bins.empty() ? 0.0f : 1.0f / static_cast<float>(bins.size());
  for (int bin : bins) {
    if (histogram.empty() || histogram.back().first != bin) histogram.emplace_back(bin, 0.0f);
    histogram.back().second += share;
  }
  return histogram;
}

}  // namespace

float colorOverlap(const Cloud& cloud, const std::vector<int>& a, const std::vector<int>& b) {
  const auto first = histogramApart(cloud, a, b);
  const auto second = histogramApart(cloud, b, a);
  float common = 0.0f;
  auto i = first.begin();
  auto j = second.begin();
  while (i != first.end() && j != second.end()) {
    if (i->first < j->first) {
      ++i;
    } else if (j->first < i->first) {
      ++j;
    } else {
      common += std::min(i->second, j->second);
      ++i;
      ++j;
    }
  }
  return std::min(common, 1.0f);
}

}  // namespace symmetry_segmentation
