// Stage 19, object_bottoms: the sides' points and inside floors within the table margin back to their segments.
#include "symmetry_segmentation/symmetry/object_bottom_stage.h"

#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"

namespace symmetry_segmentation {

void ObjectBottomStage::run(PipelineState& state) const {
  std::size_t added_points = 0;
  if (state.scene) {
    std::vector<std::vector<int>> input;
    input.reserve(state.segments.size());
    for (const CandidateSegment& segment : state.segments) {
      input.push_back(setUnion(expandToInput(state.prepared, segment.points), segment.extra_input_points));
    }
    const std::vector<std::vector<int>> added = objectBottoms(*state.scene, state.prepared, voxel_size_, input, params_);
    for (std::size_t s = 0; s < state.segments.size(); ++s) {
      std::vector<int>& extra = state.segments[s].extra_input_points;
      extra = setUnion(extra, added[s]);
      added_points += added[s].size();
    }
  }
  state.count("points_added", added_points);
}

}  // namespace symmetry_segmentation
