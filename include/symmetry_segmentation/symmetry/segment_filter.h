#pragma once
// Stage 5: keep the segments that look like whole symmetric objects, once each.

#include <vector>

#include "symmetry_segmentation/segmentation_result.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

struct CandidateSegment {
  std::vector<int> points;  ///< Working-cloud indices, sorted.
  SymmetryPlane plane;
  SegmentScores scores;
};

/// Occlusion score above s_occl, smoothness score below s_smooth, at least min_segment_points.
bool passesFilter(const CandidateSegment& segment, const SymmetryFilterParams& params);

/// Intersection over the smaller of two sorted index sets (0 when either is empty).
float overlapOfSmaller(const std::vector<int>& a, const std::vector<int>& b);

/// Among segments overlapping by more than duplicate_overlap (of the smaller one), keeps the one
/// with the cleanest boundary (lowest smoothness score, then the larger, then the earlier).
std::vector<CandidateSegment> removeDuplicates(std::vector<CandidateSegment> segments,
                                               const SymmetryFilterParams& params);

}  // namespace symmetry_segmentation
