#pragma once
// The evaluation metric of Ecins et al. (ICRA 2016), sec. V: a ground-truth object is found when
// some segment overlaps it with IoU > sigma; a segment is correct when its best IoU with an object
// of its scene is > sigma. Counts are pooled over scenes (summed, then divided).
//
// Ground-truth objects are the distinct positive labels of a scene; IoU is computed over input
// point indices, so points labelled 0 inside a segment lower its IoU. Points with a negative label
// (kIgnoredLabel) are left out: in no object, and taken out of every segment before its IoU (a
// segment of nothing else still counts, with IoU 0). Segments may overlap.

#include <cstddef>
#include <vector>

#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

/// A point left out of the evaluation (any negative label does the same).
constexpr int kIgnoredLabel = -1;

/// Best IoUs of one scene; independent of sigma, so one overlap serves every threshold.
struct SceneOverlap {
  std::vector<int> object_labels;         ///< Distinct positive labels, ascending.
  std::vector<double> object_best_iou;    ///< Per object: best IoU over all segments.
  std::vector<double> segment_best_iou;   ///< Per segment: best IoU over all objects.
};

/// Throws InputError when a segment index is outside [0, labels.size()).
SceneOverlap computeOverlap(const std::vector<int>& labels,
                            const std::vector<std::vector<int>>& segments);
SceneOverlap computeOverlap(const std::vector<int>& labels, const std::vector<Segment>& segments);

/// Counts that pool over scenes by summation.
struct MatchCounts {
  std::size_t segments = 0;
  std::size_t correct_segments = 0;  ///< Best IoU > sigma.
  std::size_t objects = 0;
  std::size_t found_objects = 0;     ///< Best IoU > sigma.
  double best_iou_sum = 0.0;         ///< Sum over objects of their best IoU.

  MatchCounts& operator+=(const MatchCounts& other);
};

/// Strictly greater than sigma: an IoU exactly at the threshold does not match.
MatchCounts countMatches(const SceneOverlap& overlap, double sigma);

struct Metrics {
  double precision = 0.0;      ///< 0 when there are no segments.
  double recall = 0.0;         ///< 0 when there are no objects.
  double f = 0.0;              ///< 2PR/(P+R); 0 when P+R = 0.
  double mean_best_iou = 0.0;  ///< Mean over objects of their best IoU; 0 when no objects.
};

Metrics computeMetrics(const MatchCounts& counts);

}  // namespace symmetry_segmentation
