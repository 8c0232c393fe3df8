// The symmetry method: prepare the scene, run the stage list, report the segments.
#include "symmetry_segmentation/symmetry/symmetry_segmenter.h"

#include <map>

#include "symmetry_segmentation/object_box.h"
#include "symmetry_segmentation/stopwatch.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"

namespace symmetry_segmentation {

SymmetrySegmenter::SymmetrySegmenter(const SegmentationConfig& config) : config_(config), stages_(makeStages(config)) {}

SegmentationResult SymmetrySegmenter::segment(const Scene& scene) const {
  Stopwatch total;
  PipelineState state = preparePipeline(scene, config_.preprocessing, config_.symmetry);
  std::map<std::string, int> runs;  // a stage listed twice is timed as "cut", then "cut#2"
  for (std::size_t i = 0; i < stages_.size(); ++i) {
    const std::string& name = config_.symmetry.stages[i];
    const int run = ++runs[name];
    state.stage_label = run == 1 ? name : name + "#" + std::to_string(run);
    Stopwatch watch;
    stages_[i]->run(state);
    state.timing_ms.emplace_back(state.stage_label, watch.elapsedMs());
  }

  SegmentationResult result;
  result.input_points = scene.size();
  result.support = supportSurface(state.prepared);
  result.segments = reportedSegments(state);
  addObjectBoxes(scene, result);
  result.timing_ms = std::move(state.timing_ms);
  result.timing_ms.emplace_back("total", total.elapsedMs());
  result.counts = std::move(state.counts);
  result.counts.emplace_back("segments", result.segments.size());
  return result;
}

}  // namespace symmetry_segmentation
