#pragma once
// Stage 5c (our addition): a segment that is two objects meeting at a concave seam.
//
// One plane can be a symmetry of two objects at once: a bowl centred on a box, a can pushed
// against the middle of a box's end face. Its cut takes both, scores as well as either object
// alone, and, being larger, would win deduplication. When each object is also found on its own
// (two nearly disjoint segments that together make up the larger one), the two are apart or meet
// along a concave crease - where separate objects touch - rather than along a smooth or convex
// edge (a box's two halves, a bowl's rim), and the larger segment's plane mirrors each part onto
// itself - two objects that happen to share a plane - rather than one part onto the other (the
// two arms of a U-shaped object, the halves of a box seen around an occluder), the larger
// segment is replaced by the two. Two parts found alone must moreover be joined by creases
// only: if any path between them within the larger segment crosses no crease, they are parts of
// one object (an L-shaped block's slab and upright meet at a crease on the inside but run on
// into each other along the outer faces, through the corner neither took).
// Objects that meet flush on one flat face (a box on a box of the same footprint) show no crease:
// nothing in the geometry tells them from one taller box, only their colours (color_seams.h).
#include <functional>
#include <vector>

#include "symmetry_segmentation/symmetry/segment_filter.h"

namespace symmetry_segmentation {

/// Whether the working-cloud link (a, b) crosses a concave crease.
using CreaseTest = std::function<bool(int a, int b)>;
/// The working-cloud point that point `index` reflects onto about `plane`, or -1 if none.
using ReflectionMatch = std::function<int(int index, const SymmetryPlane& plane)>;
/// Occlusion and smoothness scores of a segment for its plane.
using SegmentScorer = std::function<SegmentScores(const std::vector<int>& points, const SymmetryPlane& plane)>;

struct CompositeSegmentParams {
  float min_nested_fraction = 0.8f;  ///< Share of each part inside the composite.
  float min_part_fraction = 0.2f;    ///< Each part has at least this share of the composite's size...
  float max_part_fraction = 0.8f;    ///< ...and at most this share.
  float max_part_overlap = 0.1f;     ///< Parts share at most this share of the smaller part.
  float min_coverage = 0.85f;        ///< The two parts cover at least this share of the composite.
  float min_crease_fraction = 0.5f;  ///< Share of the links between the parts that cross a crease.
  float min_rest_crease_fraction = 0.9f;  ///< The same for a part not found alone (a flush face
                                          ///< running on across the seam makes it fall short).
  int min_seam_links = 5;            ///< Parts linked by fewer links are apart (no seam to judge).
  float max_swapped_fraction = 0.3f; ///< Share of a part's matched reflections (about the larger
                                     ///< segment's plane) landing on the other part, above which
                                     ///< the parts are mirror halves of one object.
};

/// Replaces every segment of `segments` that is two objects by those two (each added once, after
/// the remaining segments): two segments of `parts` that together make it up, else one segment of
/// `parts` and the rest of it (an object seen in pieces around the other is never found whole on
/// its own; the rest keeps the larger segment's
/// plane and is scored by `score`). The two must be apart or meet at a concave seam (a rest at
/// creases only), and the larger segment's plane must mirror each onto itself.
/// `neighbours[i]`: the working-cloud points linked to point i. Returns how many were replaced.
std::size_t splitCompositeSegments(std::vector<CandidateSegment>& segments, const std::vector<CandidateSegment>& parts,
                                   const std::vector<std::vector<int>>& neighbours, const CreaseTest& crease,
                                   const ReflectionMatch& match, const SegmentScorer& score,
                                   const CompositeSegmentParams& params = {});

}  // namespace symmetry_segmentation
