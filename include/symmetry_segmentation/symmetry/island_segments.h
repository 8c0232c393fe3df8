#pragma once
// Stage 5a (our addition): objects standing apart, checked by their symmetry.
//
// The graph cut finds an object as the points its plane explains; where that plane is a few
// degrees off, or is one arm's plane rather than the whole object's, the cut returns pieces
// (an L-shaped block's arm, a mug without its handle). An island - points no closer than a gap to
// any other point above the table - is often exactly one object, and the planes the cuts found
// on it say whether it is one: an island that one of them explains as a whole (it passes the
// same filter as every segment) is proposed as a segment too, and deduplication then prefers it
// to its pieces (its boundary, a gap all round, is the cleanest there is). An island of two
// objects that no plane explains together is not proposed.
#include <functional>
#include <vector>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/composite_segments.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"

namespace symmetry_segmentation {

/// Groups of cloud points linked through points closer than `gap` to each other (Euclidean
/// clusters), each sorted, of at least `min_points`.
std::vector<std::vector<int>> spatialIslands(const Cloud::ConstPtr& cloud, float gap, int min_points);

/// For each island: the plane among `segments`' planes (of segments lying mostly on the island
/// and covering a good share of it)
/// under which the island scores best; the island with that plane when it passes `filter`.
std::vector<CandidateSegment> explainedIslands(const std::vector<std::vector<int>>& islands,
                                               const std::vector<CandidateSegment>& segments,
                                               const SegmentScorer& score, const SymmetryFilterParams& filter);

}  // namespace symmetry_segmentation
