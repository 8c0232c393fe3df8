#pragma once
// Stage 5b (our addition): objects the graph cut glued onto another object's segment.
//
// A cut for one object's plane may also take a neighbour that its plane mirrors into occluded
// space (a can standing on a box, the next box of a row): occluded space is no evidence
// against it and the smooth joint holds it. When that neighbour is found on its own as a smaller
// segment nested in the larger one, and the larger segment's plane does not explain it (few of
// its points reflect onto scene points), it is another object and is taken out of the larger
// segment. A part the plane does explain (a mug's body inside the whole mug, a box's handle)
// stays.

#include <functional>
#include <vector>

#include "symmetry_segmentation/symmetry/segment_filter.h"

namespace symmetry_segmentation {

/// Whether point `index` reflects about `plane` onto a scene point. (Normals are not asked to
/// match: on thin parts such as a box's handle they are too noisy at 1 cm.)
using ReflectionExplained = std::function<bool(int index, const SymmetryPlane& plane)>;

struct NestedSegmentParams {
  float min_nested_fraction = 0.8f;   ///< Share of the smaller segment inside the larger one.
  float max_size_ratio = 0.8f;        ///< The smaller segment has at most this share of the larger's size.
  float max_explained_fraction = 0.5f;///< Below this share of explained points, it is foreign.
};

/// Removes foreign nested segments' points from the larger segments (larger ones first; each
/// segment's points stay sorted). Returns the indices of the segments that lost points; those
/// left with fewer than `min_points` points are emptied.
std::vector<std::size_t> removeForeignParts(std::vector<CandidateSegment>& segments,
                                            const ReflectionExplained& explained, int min_points,
                                            const NestedSegmentParams& params = {});

}  // namespace symmetry_segmentation
