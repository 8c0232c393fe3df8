#pragma once
// Stage 13, mirror_twins (our addition): two like objects side by side (two bowls, two bottles)
// are mirror images about the plane between them, and its cut takes both. A segment in separate
// pieces that its plane mirrors onto each other is split when the sensor saw through the space
// between them (observed free space); the pieces of one object seen around an occluder have
// unobserved space between them and stay together, and so do the uprights of a U, mirrored onto
// each other about the plane through its base, which that plane mirrors onto itself.
#include <vector>

#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// Replaces each segment whose surface-connected pieces (over the evidence's links) include two
/// or more large ones with observed free space between mirrored pairs across them, and fewer
/// pairs within a piece than across (a U's base mirrors onto itself), by those pieces (smaller
/// pieces join the large one they have most links to, else the largest), each keeping the
/// segment's plane, scored anew. Returns how many segments were split.
std::size_t splitMirrorTwins(std::vector<CandidateSegment>& segments, const SceneEvidence& evidence,
                             const MirrorTwinParams& params);

/// The stage: splitMirrorTwins on the segments.
class MirrorTwinStage : public Stage {
 public:
  explicit MirrorTwinStage(const MirrorTwinParams& params) : params_(params) {}
  void run(PipelineState& state) const override;

 private:
  MirrorTwinParams params_;
};

}  // namespace symmetry_segmentation
