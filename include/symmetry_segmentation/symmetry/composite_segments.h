#pragma once
// Stage 13, composites (our addition): a segment that is two objects meeting at a concave seam.
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
#include <vector>

#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// Replaces every segment of `segments` that is two objects by those two (each added once, after
/// the remaining segments): two segments of `parts` that together make it up, else one segment of
/// `parts` and the rest of it (an object seen in pieces around the other is never found whole on
/// its own; the rest keeps the larger segment's plane and is scored anew). The two must be apart
/// or meet at a concave seam (links crossing creases sharper than params.crease_angle_deg; a rest
/// at creases only), and the larger segment's plane must mirror each onto itself. Returns how
/// many were replaced.
std::size_t splitCompositeSegments(std::vector<CandidateSegment>& segments, const std::vector<CandidateSegment>& parts,
                                   const SceneEvidence& evidence, const CompositeSegmentParams& params);

/// The stage: splitCompositeSegments with the segments as they are as the parts.
class CompositeStage : public Stage {
 public:
  explicit CompositeStage(const CompositeSegmentParams& params) : params_(params) {}
  void run(PipelineState& state) const override;

 private:
  CompositeSegmentParams params_;
};

}  // namespace symmetry_segmentation
