#pragma once
// Stage 5b' (our addition): two objects that are each other's mirror image.
//
// Two like objects side by side (two bowls, two bottles) are mirror images about the plane
// between them, and the cut for that plane takes both: the symmetric-neighbour links join them
// although no surface does. One object can also come out as two pieces joined only by those
// links - a box seen left and right of a board in front of it - and must stay whole. The space
// between the pieces tells them apart: between two objects the sensor saw through (observed free
// space halfway between a point and its mirror image), between the pieces of one object it saw
// the object's surface or nothing (its inside, or what the board hid).
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/composite_segments.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"

namespace symmetry_segmentation {

/// Whether the sensor saw through this point (observed free space).
using ObservedFree = std::function<bool(const Eigen::Vector3f& point)>;

struct MirrorTwinParams {
  float min_part_fraction = 0.25f;  ///< Pieces with at least this share of the segment are objects.
  float min_free_fraction = 0.6f;   ///< Share of mirrored pairs across pieces whose midpoint is free.
  int min_pairs = 10;               ///< Fewer mirrored pairs across the pieces decide nothing.
};

/// Replaces each segment of `segments` whose surface-connected pieces (over `neighbours`) include
/// two or more large ones with observed free space between mirrored pairs across them by those
/// pieces (smaller pieces join the large one they have most links to, else the largest), each
/// keeping the segment's plane, scored by `score`. Returns how many segments were split.
std::size_t splitMirrorTwins(std::vector<CandidateSegment>& segments, const Cloud& cloud,
                             const std::vector<std::vector<int>>& neighbours, const ReflectionMatch& match,
                             const ObservedFree& free, const SegmentScorer& score, const MirrorTwinParams& params = {});

}  // namespace symmetry_segmentation
