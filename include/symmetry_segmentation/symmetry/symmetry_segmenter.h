#pragma once
// The symmetry method: the scene prepared once (working cloud, occupancy, graph), then the stages
// of symmetry.stages in order (stage.h; README, "The symmetry method"), each timed and counted
// under its own name.

#include <memory>
#include <vector>

#include "symmetry_segmentation/segmenter.h"
#include "symmetry_segmentation/symmetry/stage.h"

namespace symmetry_segmentation {

class SymmetrySegmenter : public Segmenter {
 public:
  /// Throws InputError when the stage list cannot run.
  explicit SymmetrySegmenter(const SegmentationConfig& config);
  std::string name() const override { return "symmetry"; }
  SegmentationResult segment(const Scene& scene) const override;

 private:
  SegmentationConfig config_;
  std::vector<std::unique_ptr<Stage>> stages_;
};

}  // namespace symmetry_segmentation
