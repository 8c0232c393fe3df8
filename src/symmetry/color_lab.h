#pragma once
// Colour helpers shared by the colour stages (color_seams.cpp, stray_color_pieces.cpp).
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "disjoint_sets.h"
#include "segment_links.h"
#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"

namespace symmetry_segmentation {

// sRGB (0-255) to CIELAB (D65 white), the space in which equal distances look about equally
// different.
inline Eigen::Vector3f toLab(const PointT& point) {
  auto linear = [](std::uint8_t channel) {
    const float c = channel / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
  };
  const float r = linear(point.r), g = linear(point.g), b = linear(point.b);
  const float x = (0.4124f * r + 0.3576f * g + 0.1805f * b) / 0.95047f;
  const float y = 0.2126f * r + 0.7152f * g + 0.0722f * b;
  const float z = (0.0193f * r + 0.1192f * g + 0.9505f * b) / 1.08883f;
  auto f = [](float t) { return t > 0.008856f ? std::cbrt(t) : 7.787f * t + 16.0f / 116.0f; };
  return {116.0f * f(y) - 16.0f, 500.0f * (f(x) - f(y)), 200.0f * (f(y) - f(z))};
}

inline float colorDifference(const Eigen::Vector3f& lab_a, const Eigen::Vector3f& lab_b) {
  const Eigen::Vector3f d = lab_a - lab_b;
  return std::sqrt(0.25f * d.x() * d.x() + d.y() * d.y() + d.z() * d.z());
}

// Colour regions of `points`: positions joined through links whose ends differ in colour (`lab`,
// per position) by at most `max_difference`.
inline DisjointSets colorRegions(const std::vector<int>& points, const std::vector<Eigen::Vector3f>& lab,
                                 const std::vector<std::vector<int>>& neighbours, float max_difference) {
  DisjointSets regions(points.size());
  forEachLink(points, neighbours, [&](int j, int k) {
    if (colorDifference(lab[j], lab[k]) <= max_difference) regions.unite(j, k);
  });
  return regions;
}

}  // namespace symmetry_segmentation
