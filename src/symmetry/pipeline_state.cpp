// The pipeline state: the scene prepared for the stages, and the segments it reports.
#include "symmetry_segmentation/symmetry/pipeline_state.h"

#include <algorithm>

#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/segment_order.h"
#include "symmetry_segmentation/stopwatch.h"
#include "symmetry_segmentation/symmetry/completion.h"
#include "symmetry_segmentation/symmetry/graph_evidence.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"
#include "symmetry_segmentation/symmetry/symmetric_graph_cut.h"

namespace symmetry_segmentation {

PipelineState::PipelineState() = default;
PipelineState::~PipelineState() = default;
PipelineState::PipelineState(PipelineState&&) noexcept = default;
PipelineState& PipelineState::operator=(PipelineState&&) noexcept = default;

void PipelineState::count(const std::string& what, std::size_t value) {
  counts.emplace_back(stage_label + "." + what, value);
}

PipelineState preparePipeline(const Scene& scene, const PreprocessParams& preprocessing, const SymmetryParams& params) {
  Stopwatch stage;
  PipelineState state;
  state.scene = &scene;
  state.threads = params.threads;
  state.has_color = scene.has_color;
  state.prepared = preprocess(scene, preprocessing);
  state.cloud = state.prepared.cloud;
  if (state.prepared.has_table) state.up = state.prepared.table_plane.head<3>().normalized();
  state.timing_ms.emplace_back("preprocess", stage.lap());

  RayCastOptions ray_cast;
  ray_cast.resolution = preprocessing.voxel_size;
  ray_cast.from_depth_image = params.depth_image_occupancy;
  state.occupancy = std::make_unique<OccupancyMap>(occupancyForScene(scene, ray_cast));
  state.timing_ms.emplace_back("occupancy", stage.lap());

  std::optional<TableTop> table;
  if (state.prepared.has_table) table = state.prepared.tableTop();
  // On a coarser working grid the points stand farther apart: isolated means no other within
  // two voxels at least, else every point of a 3 cm grid would be.
  SymmetryCutParams cut = params.cut;
  if (cut.isolated_radius > 0.0f) cut.isolated_radius = std::max(cut.isolated_radius, 2.0f * preprocessing.voxel_size);
  state.graph = std::make_unique<SymmetricGraphCut>(state.cloud, *state.occupancy, table, cut);
  state.evidence = std::make_unique<GraphEvidence>(*state.graph, *state.occupancy, params.filter);
  state.timing_ms.emplace_back("graph", stage.lap());
  const PreprocessedScene::Dropped& dropped = state.prepared.dropped;
  state.counts.emplace_back("dropped.out_of_range", dropped.out_of_range);
  state.counts.emplace_back("dropped.on_table", dropped.on_table);
  state.counts.emplace_back("dropped.too_high", dropped.too_high);
  state.counts.emplace_back("dropped.off_support", dropped.off_support);
  state.counts.emplace_back("dropped.outside_roi", dropped.outside_roi);
  state.counts.emplace_back("working_points", state.cloud->size());
  return state;
}

namespace {

/// The completed object: the added points, the box around them and the visible input points (down
/// to the support when the object rests on it), and the symmetry frame at the centroid of the working points and the added ones (both 1 cm apart).
SegmentCompletion completedObject(const PipelineState& state, const CandidateSegment& candidate,
                                  const std::vector<int>& input_points) {
  SegmentCompletion completion;
  completion.points = *candidate.completion;
  std::vector<Eigen::Vector3f> visible;
  visible.reserve(input_points.size());
  for (int index : input_points) visible.push_back(state.scene->cloud->points[index].getVector3fMap());
  const std::optional<Eigen::Vector3f> up = state.up ? state.up : state.scene->up;
  completion.box = groundedBox(completedBox(visible, completion.points, up, kAddedPointsTrim, state.prepared.table_noise),
                               candidate.grounded);
  if (candidate.rests_on_support && state.prepared.has_table) {
    completion.box = restingBox(completion.box, state.prepared.tableTop(), kTableBandMargins * state.prepared.table_margin);
  }
  completion.points.insert(completion.points.end(), candidate.grounded.begin(), candidate.grounded.end());
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  for (int index : candidate.points) centroid += state.cloud->points[index].getVector3fMap();
  for (const Eigen::Vector3f& p : completion.points) centroid += p;
  const std::size_t count = candidate.points.size() + completion.points.size();
  if (count > 0) centroid /= static_cast<float>(count);
  const Eigen::Isometry3f frame = symmetryFrame(centroid, candidate.plane, up);
  completion.frame_position = frame.translation();
  completion.frame_orientation = Eigen::Quaternionf(frame.linear()).normalized();
  return completion;
}

}  // namespace

std::vector<Segment> reportedSegments(const PipelineState& state) {
  std::vector<Segment> segments;
  segments.reserve(state.segments.size());
  for (const CandidateSegment& candidate : state.segments) {
    Segment segment;
    segment.indices = setUnion(expandToInput(state.prepared, candidate.points), candidate.extra_input_points);
    segment.symmetry = candidate.plane;
    segment.scores = candidate.scores;
    if (candidate.completion) segment.completion = completedObject(state, candidate, segment.indices);
    segments.push_back(std::move(segment));
  }
  sortSegmentsBySize(segments);
  return segments;
}

}  // namespace symmetry_segmentation
