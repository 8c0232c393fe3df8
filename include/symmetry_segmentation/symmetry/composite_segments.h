#pragma once
// Stage 14, composites (our addition): one plane can be a symmetry of two objects at once (a bowl
// centred on a box), and its cut takes both and, being larger, wins deduplication. A segment that
// two segments found alone make up (or one and the rest), apart or meeting only at concave creases
// and each mirrored onto itself by its plane, is replaced by the two; parts that also run on into
// each other without a crease (an L-shaped block's slab and upright) stay one object, and so do
// parts of one colour or one print: seen from where the slab's end face is hidden, an L-shaped
// block is to the geometry a low box against a tall one, and only its colours say it is one
// object (one print's palette over both parts: color_histogram.h).
#include <vector>

#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// Replaces every segment of `segments` that is two objects by those two (each added once, after
/// the remaining segments): two segments of `parts` that together make it up, else one segment of
/// `parts` and the rest of it (an object seen in pieces around the other is never found whole on
/// its own; the rest keeps the larger segment's plane and is scored anew), else two segments of
/// `parts` that mirror onto each other - one object's pieces either side of the other, which is
/// then never found alone - and the rest (both on the larger segment's plane). The two must be apart
/// or meet at a concave seam (links crossing creases sharper than params.crease_angle_deg; a rest
/// at creases only), the larger segment's plane must mirror each onto itself, and where
/// params.use_color their mean colours must differ by params.min_color_difference and they must
/// share less than params.min_color_overlap of their colours. Returns how many were replaced.
std::size_t splitCompositeSegments(std::vector<CandidateSegment>& segments, const std::vector<CandidateSegment>& parts,
                                   const SceneEvidence& evidence, const CompositeSegmentParams& params);

/// The stage: splitCompositeSegments with the segments and every candidate (filtered out or
/// not) as the parts; colour where the scene has it.
class CompositeStage : public Stage {
 public:
  explicit CompositeStage(const CompositeSegmentParams& params) : params_(params) {}
  void run(PipelineState& state) const override;

 private:
  CompositeSegmentParams params_;
};

}  // namespace symmetry_segmentation
