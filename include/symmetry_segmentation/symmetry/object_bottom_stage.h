#pragma once
// Stage 19, object_bottoms (our addition): each segment gets back its sides' points within the
// table margin, which preprocessing dropped with the table (object_bottoms.h: 5-15 % of a small
// box, enough to push a correct segment under IoU 0.9), and a hollow object's inside floor
// (object_floors.h: a third of a bowl seen from above). Runs last, on the final segments, since
// each strip goes to the segment nearest above it.
#include "symmetry_segmentation/object_bottoms.h"
#include "symmetry_segmentation/symmetry/stage.h"

namespace symmetry_segmentation {

class ObjectBottomStage : public Stage {
 public:
  ObjectBottomStage(const ObjectBottomParams& params, float voxel_size) : params_(params), voxel_size_(voxel_size) {}
  void run(PipelineState& state) const override;

 private:
  ObjectBottomParams params_;
  float voxel_size_;
};

}  // namespace symmetry_segmentation
