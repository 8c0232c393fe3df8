#include "symmetry_segmentation/evaluation/segmentation_metric.h"

#include <algorithm>
#include <map>
#include <string>
#include <unordered_map>

#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {

SceneOverlap computeOverlap(const std::vector<int>& labels,
                            const std::vector<std::vector<int>>& segments) {
  std::map<int, std::size_t> object_sizes;  // ordered: object_labels come out ascending
  for (int label : labels) {
    if (label > 0) ++object_sizes[label];
  }

  SceneOverlap overlap;
  std::unordered_map<int, std::size_t> object_position;
  for (const auto& [label, size] : object_sizes) {
    object_position[label] = overlap.object_labels.size();
    overlap.object_labels.push_back(label);
  }
  overlap.object_best_iou.assign(overlap.object_labels.size(), 0.0);
  overlap.segment_best_iou.reserve(segments.size());

  for (std::size_t s = 0; s < segments.size(); ++s) {
    // Duplicated indices would inflate the segment's size; count each point once.
    std::vector<int> indices = segments[s];
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());

    std::unordered_map<int, std::size_t> intersection;
    std::size_t ignored = 0;
    for (int index : indices) {
      if (index < 0 || static_cast<std::size_t>(index) >= labels.size()) {
        throw InputError("segment " + std::to_string(s) + " has point index " +
                         std::to_string(index) + " outside the scene's " +
                         std::to_string(labels.size()) + " points");
      }
      const int label = labels[static_cast<std::size_t>(index)];
      if (label > 0) ++intersection[label];
      if (label < 0) ++ignored;
    }
    const std::size_t segment_size = indices.size() - ignored;

    double segment_best = 0.0;
    for (const auto& [label, shared] : intersection) {
      const double union_size =
          static_cast<double>(segment_size + object_sizes[label] - shared);
      const double iou = static_cast<double>(shared) / union_size;
      segment_best = std::max(segment_best, iou);
      double& object_best = overlap.object_best_iou[object_position[label]];
      object_best = std::max(object_best, iou);
    }
    overlap.segment_best_iou.push_back(segment_best);
  }
  return overlap;
}

SceneOverlap computeOverlap(const std::vector<int>& labels, const std::vector<Segment>& segments) {
  std::vector<std::vector<int>> index_sets;
  index_sets.reserve(segments.size());
  for (const Segment& segment : segments) index_sets.push_back(segment.indices);
  return computeOverlap(labels, index_sets);
}

MatchCounts& MatchCounts::operator+=(const MatchCounts& other) {
  segments += other.segments;
  correct_segments += other.correct_segments;
  objects += other.objects;
  found_objects += other.found_objects;
  best_iou_sum += other.best_iou_sum;
  return *this;
}

MatchCounts countMatches(const SceneOverlap& overlap, double sigma) {
  MatchCounts counts;
  counts.segments = overlap.segment_best_iou.size();
  counts.objects = overlap.object_best_iou.size();
  for (double iou : overlap.segment_best_iou) {
    if (iou > sigma) ++counts.correct_segments;
  }
  for (double iou : overlap.object_best_iou) {
    if (iou > sigma) ++counts.found_objects;
    counts.best_iou_sum += iou;
  }
  return counts;
}

Metrics computeMetrics(const MatchCounts& counts) {
  Metrics metrics;
  if (counts.segments > 0) {
    metrics.precision =
        static_cast<double>(counts.correct_segments) / static_cast<double>(counts.segments);
  }
  if (counts.objects > 0) {
    metrics.recall = static_cast<double>(counts.found_objects) / static_cast<double>(counts.objects);
    metrics.mean_best_iou = counts.best_iou_sum / static_cast<double>(counts.objects);
  }
  const double sum = metrics.precision + metrics.recall;
  if (sum > 0.0) metrics.f = 2.0 * metrics.precision * metrics.recall / sum;
  return metrics;
}

}  // namespace symmetry_segmentation
