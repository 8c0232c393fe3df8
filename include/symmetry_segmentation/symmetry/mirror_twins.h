#pragma once
// Stage 12, mirror_twins (our addition): two objects that are each other's mirror image.
//
// Two like objects side by side (two bowls, two bottles) are mirror images about the plane
// between them, and the cut for that plane takes both: the symmetric-neighbour links join them
// although no surface does. One object can also come out as two pieces joined only by those
// links - a box seen left and right of a board in front of it - and must stay whole. The space
// between the pieces tells them apart: between two objects the sensor saw through (observed free
// space halfway between a point and its mirror image), between the pieces of one object it saw
// the object's surface or nothing (its inside, or what the board hid).
#include <vector>

#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// Replaces each segment whose surface-connected pieces (over the evidence's links) include two
/// or more large ones with observed free space between mirrored pairs across them by those
/// pieces (smaller pieces join the large one they have most links to, else the largest), each
/// keeping the segment's plane, scored anew. Returns how many segments were split.
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
