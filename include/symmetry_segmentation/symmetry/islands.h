#pragma once
// Stage 6, islands (our addition): groups of points that no point outside comes closer to than a
// gap (Euclidean clusters of the working cloud). An island is often exactly one object, with the
// cleanest boundary there is; the footprints and island_segments stages use them.
#include <vector>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

/// Groups of cloud points linked through points closer than `gap` to each other, each sorted, of
/// at least `min_points`.
std::vector<std::vector<int>> spatialIslands(const Cloud::ConstPtr& cloud, float gap, int min_points);

/// The stage: the islands of at least the filter's min_segment_points into the state.
class IslandStage : public Stage {
 public:
  IslandStage(const IslandParams& params, const SymmetryFilterParams& filter) : params_(params), filter_(filter) {}
  void run(PipelineState& state) const override;

 private:
  IslandParams params_;
  SymmetryFilterParams filter_;
};

}  // namespace symmetry_segmentation
