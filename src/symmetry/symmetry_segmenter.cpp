#include "symmetry_segmentation/symmetry/symmetry_segmenter.h"

#include <algorithm>
#include <cmath>

#include "symmetry_segmentation/object_bottoms.h"
#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/parallel_for.h"
#include "symmetry_segmentation/preprocessing.h"
#include "symmetry_segmentation/segment_order.h"
#include "symmetry_segmentation/stopwatch.h"
#include "symmetry_segmentation/symmetry/color_seams.h"
#include "symmetry_segmentation/symmetry/composite_segments.h"
#include "symmetry_segmentation/symmetry/footprint_hypotheses.h"
#include "symmetry_segmentation/symmetry/island_segments.h"
#include "symmetry_segmentation/symmetry/mirror_twins.h"
#include "symmetry_segmentation/symmetry/nested_segments.h"
#include "symmetry_segmentation/symmetry/normal_edge_curves.h"
#include "symmetry_segmentation/symmetry/plane_refinement.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stray_color_pieces.h"
#include "symmetry_segmentation/symmetry/smoothness_weight.h"
#include "symmetry_segmentation/symmetry/symmetric_graph_cut.h"
#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"
#include "symmetry_segmentation/symmetry/upright_hypotheses.h"

namespace symmetry_segmentation {
namespace {

// Weight of a matched reflection against one contradicted by free space when orienting a plane
// through an axis.
constexpr float kMatchTieBreak = 0.05f;
// An island of which no passing segment covers this share gets hypotheses of its own.
constexpr float kMinIslandCoverage = 0.9f;

}  // namespace

SegmentationResult SymmetrySegmenter::segment(const Scene& scene) const {
  Stopwatch total, stage;
  SegmentationResult result;
  result.input_points = scene.size();
  const PreprocessedScene prepared = preprocess(scene, preprocessing_);
  result.timing_ms.emplace_back("preprocess", stage.lap());

  RayCastOptions ray_cast;
  ray_cast.resolution = preprocessing_.voxel_size;
  const OccupancyMap occupancy = occupancyForScene(scene, ray_cast);
  result.timing_ms.emplace_back("occupancy", stage.lap());

  const Cloud& cloud = *prepared.cloud;
  std::optional<PlaneCoefficients> table;
  if (prepared.has_table) table = prepared.table_plane;
  const SymmetricGraphCut graph(prepared.cloud, occupancy, table, params_.cut);
  result.timing_ms.emplace_back("graph", stage.lap());

  const std::vector<int> surfaces = mergedSegmentLabels(cloud, params_.detection);
  const auto curves = extractNormalEdgeCurves(cloud, surfaces, params_.detection);
  result.timing_ms.emplace_back("curves", stage.lap());
  auto hypotheses = detectSymmetryHypotheses(cloud, curves, params_.detection);
  if (params_.detection.upright_hypotheses && prepared.has_table) {
    const Eigen::Vector3f up = prepared.table_plane.head<3>().normalized();
    // The data term's own verdict. Every plane through a true axis is a symmetry, so what
    // decides is contradiction (reflections into free space: a mug's handle mirrored beside
    // it); matches only break ties, else the bisector of whatever arc the views happened to
    // cover would win.
    const ReflectionScore score = [&graph](int index, const SymmetryPlane& plane) {
      const ReflectionEvidence evidence = graph.dataTerm(index, plane);
      if (evidence.landing == ReflectionLanding::OnPoint) return kMatchTieBreak * evidence.foreground_strength;
      return evidence.landing == ReflectionLanding::Free ? -evidence.cost_foreground : 0.0f;
    };
    appendDistinctHypotheses(hypotheses, uprightHypotheses(cloud, surfaces, up, UprightHypothesisParams(), score),
                             params_.detection.merge_plane_angle_deg, params_.detection.merge_plane_distance);
  }
  result.timing_ms.emplace_back("hypotheses", stage.lap());


  // Hypotheses are independent; results are stored by index, so any thread count gives the
  // same answer.
  std::vector<CandidateSegment> candidates;
  std::vector<char> cut_again;  // per index: no shared counter between threads
  auto cutFrom = [&](std::size_t first) {
    candidates.resize(hypotheses.size());
    parallelFor(hypotheses.size() - first, params_.threads, [&](std::size_t k) {
      const std::size_t i = first + k;
      candidates[i].plane = hypotheses[i].plane;
      candidates[i].points = graph.segment(hypotheses[i].plane, hypotheses[i].anchor);
    });
  };
  auto refineFrom = [&](std::size_t first) {
    cut_again.resize(candidates.size(), 0);
    parallelFor(candidates.size() - first, params_.threads, [&](std::size_t k) {
      const std::size_t i = first + k;
      CandidateSegment& candidate = candidates[i];
      if (static_cast<int>(candidate.points.size()) < params_.filter.min_segment_points) return;
      const SymmetryPlane before = candidate.plane;
      candidate.plane = refinePlane(cloud, candidate.points, candidate.plane, params_.refinement, params_.detection);
      // The same plane would give the same cut.
      const bool moved = candidate.plane.normal != before.normal || candidate.plane.distance != before.distance;
      if (params_.refinement.enabled && moved) {
        candidate.points = graph.segment(candidate.plane, hypotheses[i].anchor);
        cut_again[i] = 1;
      }
      candidate.scores = graph.scores(candidate.points, candidate.plane, params_.filter);
    });
  };
  cutFrom(0);
  result.timing_ms.emplace_back("graph_cut", stage.lap());
  refineFrom(0);
  result.timing_ms.emplace_back("refinement", stage.lap());

  // Islands no passing segment covers get the planes of their footprint (footprint_hypotheses.h).
  std::vector<std::vector<int>> islands;
  if (params_.filter.island_gap > 0.0f) {
    islands = spatialIslands(prepared.cloud, params_.filter.island_gap, params_.filter.min_segment_points);
  }
  const std::size_t first_footprint = hypotheses.size();
  if (params_.detection.upright_hypotheses && prepared.has_table) {
    std::vector<CandidateSegment> passing_so_far;
    for (const CandidateSegment& candidate : candidates) {
      if (passesFilter(candidate, params_.filter)) passing_so_far.push_back(candidate);
    }
    const Eigen::Vector3f up = prepared.table_plane.head<3>().normalized();
    for (const auto& island : groupsNoSegmentCovers(islands, passing_so_far, kMinIslandCoverage)) {
      for (auto& hypothesis : footprintHypotheses(cloud, island, up)) hypotheses.push_back(std::move(hypothesis));
    }
    cutFrom(first_footprint);
    refineFrom(first_footprint);
  }
  result.timing_ms.emplace_back("footprints", stage.lap());

  // Scores and reflection matches the filtering stages share.
  const SegmentScorer score = [&graph, this](const std::vector<int>& points, const SymmetryPlane& plane) {
    return graph.scores(points, plane, params_.filter);
  };
  const ReflectionMatch match = [&graph](int index, const SymmetryPlane& plane) {
    const ReflectionEvidence evidence = graph.dataTerm(index, plane);
    return evidence.landing == ReflectionLanding::OnPoint ? evidence.match : -1;
  };
  // Islands one of the planes explains whole (island_segments.h), judged before the segments
  // move on.
  std::vector<CandidateSegment> island_segments;
  if (params_.filter.island_gap > 0.0f) island_segments = explainedIslands(islands, candidates, score, params_.filter);
  const std::size_t islands_explained = island_segments.size();
  // The candidates stay as they are: a part split off at a colour seam may take one's plane.
  std::vector<CandidateSegment> passing;
  std::size_t non_empty = 0;
  for (const auto& candidate : candidates) {
    if (static_cast<int>(candidate.points.size()) >= params_.filter.min_segment_points) ++non_empty;
    if (passesFilter(candidate, params_.filter)) passing.push_back(candidate);
  }
  for (CandidateSegment& island : island_segments) passing.push_back(std::move(island));
  const std::size_t passed_filter = passing.size();
  // Two like objects the plane between them mirrors onto each other (mirror_twins.h).
  std::size_t split_twins = 0;
  if (params_.filter.twin_free_fraction > 0.0f) {
    const ObservedFree free = [&occupancy](const Eigen::Vector3f& point) {
      return occupancy.classify(point) == Occupancy::Free;
    };
    MirrorTwinParams twins;
    twins.min_free_fraction = params_.filter.twin_free_fraction;
    split_twins = splitMirrorTwins(passing, cloud, graph.neighbours(), match, free, score, twins);
  }
  // Two objects one plane mirrors together, each also found alone (composite_segments.h).
  std::size_t split_composites = 0;
  if (params_.filter.seam_crease_angle_deg > 0.0f) {
    const float min_crease_cos = std::cos(params_.filter.seam_crease_angle_deg * static_cast<float>(M_PI) / 180.0f);
    const CreaseTest crease = [&cloud, min_crease_cos](int a, int b) {
      const auto& p = cloud[a];
      const auto& q = cloud[b];
      const Eigen::Vector3f n_p = p.getNormalVector3fMap();
      const Eigen::Vector3f n_q = q.getNormalVector3fMap();
      return n_p.dot(n_q) < min_crease_cos && !isConvexLink(p.getVector3fMap(), n_p, q.getVector3fMap(), n_q);
    };
    const std::vector<CandidateSegment> parts = passing;
    split_composites = splitCompositeSegments(passing, parts, graph.neighbours(), crease, match, score);
  }
  // Take objects the cut glued onto another object's segment back out of it (nested_segments.h).
  const ReflectionExplained explained = [&graph](int index, const SymmetryPlane& plane) {
    const ReflectionEvidence evidence = graph.dataTerm(index, plane);
    return evidence.landing == ReflectionLanding::OnPoint;
  };
  // What is left keeps its place even if its recomputed scores would now fail the filter:
  // taking the glued object out cuts the smooth links it shared with it, which is no fault of
  // the remaining object.
  for (std::size_t i : removeForeignParts(passing, explained, params_.filter.min_segment_points)) {
    if (!passing[i].points.empty()) passing[i].scores = graph.scores(passing[i].points, passing[i].plane, params_.filter);
  }
  passing.erase(std::remove_if(passing.begin(), passing.end(),
                               [](const CandidateSegment& c) { return c.points.empty(); }),
                passing.end());
  // Flush objects of different colours (color_seams.h).
  const bool split_colors = scene.has_color && params_.filter.color_seam_difference > 0.0f;
  std::size_t split_colored = 0;
  if (split_colors) {
    ColorSeamParams colors;
    colors.max_link_difference = params_.filter.color_seam_difference;
    colors.min_part_points = params_.filter.min_segment_points;
    colors.flat_link_angle_deg = params_.filter.smooth_normal_angle_deg;
    split_colored = splitAtColorSeams(passing, candidates, cloud, graph.neighbours(), match, score, colors);
  }
  auto kept = removeDuplicates(std::move(passing), params_.filter);
  // Strips of a neighbour's colour go to that neighbour (stray_color_pieces.h).
  std::size_t moved_colored = 0;
  if (split_colors) {
    moved_colored = moveStrayColorPieces(kept, cloud, graph.neighbours(), params_.filter.color_seam_difference);
  }
  for (const auto& candidate : kept) {
    Segment segment;
    segment.indices = expandToInput(prepared, candidate.points);
    segment.symmetry = candidate.plane;
    segment.scores = candidate.scores;
    result.segments.push_back(std::move(segment));
  }
  restoreObjectBottoms(scene, prepared, preprocessing_, result.segments);
  sortSegmentsBySize(result.segments);
  result.timing_ms.emplace_back("filtering", stage.lap());
  result.timing_ms.emplace_back("total", total.elapsedMs());

  result.counts = {{"working_points", cloud.size()},
                   {"curves", curves.size()},
                   {"hypotheses", hypotheses.size()},
                   {"footprint_hypotheses", hypotheses.size() - first_footprint},
                   {"graph_cuts", hypotheses.size() + std::count(cut_again.begin(), cut_again.end(), 1)},
                   {"segments_before_filtering", non_empty},
                   {"segments_after_filtering", passed_filter},
                   {"islands_explained", islands_explained},
                   {"mirror_twins_split", split_twins},
                   {"composite_segments_split", split_composites},
                   {"color_seams_split", split_colored},
                   {"color_points_moved", moved_colored},
                   {"segments_after_deduplication", result.segments.size()}};
  return result;
}

}  // namespace symmetry_segmentation
