#pragma once
#include <algorithm>
#include <vector>

#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

/// Largest first, ties by first index: a stable, reproducible order for reports and colours.
inline void sortSegmentsBySize(std::vector<Segment>& segments) {
  std::sort(segments.begin(), segments.end(), [](const Segment& a, const Segment& b) {
    if (a.indices.size() != b.indices.size()) return a.indices.size() > b.indices.size();
    return a.indices < b.indices;
  });
}

}  // namespace symmetry_segmentation
