#pragma once
// What the stages of the symmetry method work on: the scene prepared once (working cloud,
// occupancy, the graph and its evidence) and what the stages make of it, in the order they
// usually make it: surfaces and curves, islands, hypotheses, a candidate segment per hypothesis,
// and the segments that will be reported. Counts and timings of every stage go with it.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/preprocessing.h"
#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"
#include "symmetry_segmentation/symmetry/normal_edge_curves.h"
#include "symmetry_segmentation/symmetry/scene_evidence.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"

namespace symmetry_segmentation {

class OccupancyMap;
class SymmetricGraphCut;

struct PipelineState {
  PipelineState();
  ~PipelineState();
  PipelineState(PipelineState&&) noexcept;
  PipelineState& operator=(PipelineState&&) noexcept;

  // ---- The scene, prepared before the first stage (preparePipeline) ------------------------
  const Scene* scene = nullptr;  ///< The input (object bottoms go back to its points).
  PreprocessedScene prepared;    ///< Working cloud, table, the map back to input points.
  Cloud::ConstPtr cloud;         ///< The working cloud (prepared.cloud).
  bool has_color = false;
  std::optional<Eigen::Vector3f> up;  ///< The table's unit normal, when there is a table.
  std::unique_ptr<OccupancyMap> occupancy;
  std::unique_ptr<SymmetricGraphCut> graph;
  std::unique_ptr<SceneEvidence> evidence;  ///< Over graph and occupancy (or a test's fake).
  int threads = 0;                          ///< For independent hypotheses; 0 = all cores.

  // ---- What the stages make ----------------------------------------------------------------
  std::vector<int> surfaces;  ///< Merged-supervoxel label per working point (0 = none).
  std::vector<Curve> curves;
  std::vector<std::vector<int>> islands;  ///< Sorted working-cloud indices.
  std::vector<SymmetryHypothesis> hypotheses;
  std::vector<CandidateSegment> candidates;  ///< candidates[i] is the cut of hypotheses[i].
  std::size_t refined = 0;                    ///< candidates[0, refined) have been refined.
  std::vector<CandidateSegment> segments;     ///< What will be reported.

  // ---- Accounting ----------------------------------------------------------------------------
  std::string stage_label;  ///< The running stage ("cut", "cut#2" on its second run).
  Counts counts;
  Timings timing_ms;
  /// Records `value` as "<running stage>.<what>".
  void count(const std::string& what, std::size_t value);
};

/// The scene prepared for the stages: preprocessing, occupancy, the graph and its evidence, each
/// timed. Throws InputError when nothing is left to segment.
PipelineState preparePipeline(const Scene& scene, const PreprocessParams& preprocessing, const SymmetryParams& params);

/// The segments as input-cloud indices (their voxels' points and any input points a stage gave
/// them), largest first.
std::vector<Segment> reportedSegments(const PipelineState& state);

}  // namespace symmetry_segmentation
