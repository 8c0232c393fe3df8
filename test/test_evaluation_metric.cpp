// Hand-made cases of the paper's metric; every expected P/R/F below is computed by hand.
#include <gtest/gtest.h>

#include <vector>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/evaluation/segmentation_metric.h"

namespace ss = symmetry_segmentation;

namespace {

using Segments = std::vector<std::vector<int>>;

// 10 points: 0-1 background, 2-5 object 1, 6-9 object 2.
const std::vector<int> kLabels = {0, 0, 1, 1, 1, 1, 2, 2, 2, 2};

ss::Metrics metricsAt(const std::vector<int>& labels, const Segments& segments, double sigma) {
  return ss::computeMetrics(ss::countMatches(ss::computeOverlap(labels, segments), sigma));
}

}  // namespace

TEST(EvaluationMetric, PerfectSegmentation) {
  const Segments segments = {{2, 3, 4, 5}, {6, 7, 8, 9}};
  for (double sigma : {0.5, 0.75, 0.9}) {
    const ss::Metrics m = metricsAt(kLabels, segments, sigma);
    EXPECT_DOUBLE_EQ(m.precision, 1.0);
    EXPECT_DOUBLE_EQ(m.recall, 1.0);
    EXPECT_DOUBLE_EQ(m.f, 1.0);
    EXPECT_DOUBLE_EQ(m.mean_best_iou, 1.0);
  }
}

TEST(EvaluationMetric, OverSegmentationFindsNothingAtHalf) {
  // Object 1 split 2+2: each half has IoU 2/4 = 0.5, not > 0.5. Object 2 split 3+1: IoU 0.75, 0.25.
  const Segments segments = {{2, 3}, {4, 5}, {6, 7, 8}, {9}};
  const ss::SceneOverlap overlap = ss::computeOverlap(kLabels, segments);
  ASSERT_EQ(overlap.segment_best_iou.size(), 4u);
  EXPECT_DOUBLE_EQ(overlap.segment_best_iou[2], 0.75);
  EXPECT_DOUBLE_EQ(overlap.segment_best_iou[3], 0.25);

  const ss::Metrics m = ss::computeMetrics(ss::countMatches(overlap, 0.5));
  EXPECT_DOUBLE_EQ(m.precision, 1.0 / 4.0);  // only {6,7,8}
  EXPECT_DOUBLE_EQ(m.recall, 1.0 / 2.0);     // only object 2
  EXPECT_DOUBLE_EQ(m.f, 2.0 * 0.25 * 0.5 / 0.75);
  EXPECT_DOUBLE_EQ(m.mean_best_iou, (0.5 + 0.75) / 2.0);

  const ss::Metrics strict = metricsAt(kLabels, segments, 0.75);  // 0.75 is not > 0.75
  EXPECT_DOUBLE_EQ(strict.precision, 0.0);
  EXPECT_DOUBLE_EQ(strict.recall, 0.0);
  EXPECT_DOUBLE_EQ(strict.f, 0.0);
}

TEST(EvaluationMetric, UnderSegmentationMergeLosesBothObjects) {
  // One segment holding both objects: IoU 4/8 with each.
  const ss::Metrics m = metricsAt(kLabels, {{2, 3, 4, 5, 6, 7, 8, 9}}, 0.5);
  EXPECT_DOUBLE_EQ(m.precision, 0.0);
  EXPECT_DOUBLE_EQ(m.recall, 0.0);
  EXPECT_DOUBLE_EQ(m.f, 0.0);
  EXPECT_DOUBLE_EQ(m.mean_best_iou, 0.5);
}

TEST(EvaluationMetric, SpuriousSegmentLowersPrecisionOnly) {
  // A segment made only of background points matches no object.
  const ss::Metrics m = metricsAt(kLabels, {{2, 3, 4, 5}, {6, 7, 8, 9}, {0, 1}}, 0.9);
  EXPECT_DOUBLE_EQ(m.precision, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(m.recall, 1.0);
  EXPECT_DOUBLE_EQ(m.f, 2.0 * (2.0 / 3.0) / (2.0 / 3.0 + 1.0));
  EXPECT_DOUBLE_EQ(m.mean_best_iou, 1.0);
}

TEST(EvaluationMetric, OverlappingSegmentsAreEachJudged) {
  // {2,3,4,5} IoU 1; {3,4,5,6}: with object 1 3/5 = 0.6, with object 2 1/7 -> best 0.6;
  // {6,7,8,9} IoU 1. Both objects found; at 0.5 all three segments are correct, at 0.75 two.
  const Segments segments = {{2, 3, 4, 5}, {3, 4, 5, 6}, {6, 7, 8, 9}};
  const ss::SceneOverlap overlap = ss::computeOverlap(kLabels, segments);
  EXPECT_DOUBLE_EQ(overlap.segment_best_iou[1], 0.6);

  const ss::Metrics half = ss::computeMetrics(ss::countMatches(overlap, 0.5));
  EXPECT_DOUBLE_EQ(half.precision, 1.0);
  EXPECT_DOUBLE_EQ(half.recall, 1.0);
  const ss::Metrics high = ss::computeMetrics(ss::countMatches(overlap, 0.75));
  EXPECT_DOUBLE_EQ(high.precision, 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(high.recall, 1.0);
}

TEST(EvaluationMetric, IouExactlyAtThresholdIsNotAMatch) {
  // 10 points of object 1; a segment with 9 of them has IoU 9/10 = 0.9 exactly.
  const std::vector<int> labels(10, 1);
  const Segments segments = {{0, 1, 2, 3, 4, 5, 6, 7, 8}};
  EXPECT_DOUBLE_EQ(ss::computeOverlap(labels, segments).object_best_iou[0], 0.9);
  const ss::MatchCounts at = ss::countMatches(ss::computeOverlap(labels, segments), 0.9);
  EXPECT_EQ(at.found_objects, 0u);
  EXPECT_EQ(at.correct_segments, 0u);
  const ss::MatchCounts below = ss::countMatches(ss::computeOverlap(labels, segments), 0.89);
  EXPECT_EQ(below.found_objects, 1u);
  EXPECT_EQ(below.correct_segments, 1u);

  // IoU 2/4 = 0.5 exactly: not found at sigma 0.5.
  EXPECT_EQ(ss::countMatches(ss::computeOverlap(kLabels, {{2, 3}}), 0.5).found_objects, 0u);
}

TEST(EvaluationMetric, EmptySegmentListGivesZeroPrecisionAndRecall) {
  const ss::MatchCounts counts = ss::countMatches(ss::computeOverlap(kLabels, Segments{}), 0.5);
  EXPECT_EQ(counts.segments, 0u);
  EXPECT_EQ(counts.objects, 2u);
  const ss::Metrics m = ss::computeMetrics(counts);
  EXPECT_DOUBLE_EQ(m.precision, 0.0);
  EXPECT_DOUBLE_EQ(m.recall, 0.0);
  EXPECT_DOUBLE_EQ(m.f, 0.0);
  EXPECT_DOUBLE_EQ(m.mean_best_iou, 0.0);
}

TEST(EvaluationMetric, SceneWithoutObjectsHasZeroRecall) {
  const std::vector<int> background(5, 0);
  const ss::MatchCounts counts = ss::countMatches(ss::computeOverlap(background, {{0, 1}}), 0.5);
  EXPECT_EQ(counts.objects, 0u);
  EXPECT_EQ(counts.segments, 1u);
  const ss::Metrics m = ss::computeMetrics(counts);
  EXPECT_DOUBLE_EQ(m.precision, 0.0);
  EXPECT_DOUBLE_EQ(m.recall, 0.0);
  EXPECT_DOUBLE_EQ(m.f, 0.0);
}

TEST(EvaluationMetric, BackgroundPointsInSegmentLowerIou) {
  // Object 1 plus both background points: IoU 4/6; plus one: 4/5 = 0.8.
  EXPECT_DOUBLE_EQ(ss::computeOverlap(kLabels, {{0, 1, 2, 3, 4, 5}}).object_best_iou[0], 4.0 / 6.0);
  const Segments one_extra = {{0, 2, 3, 4, 5}};
  EXPECT_DOUBLE_EQ(ss::computeOverlap(kLabels, one_extra).object_best_iou[0], 0.8);
  EXPECT_EQ(ss::countMatches(ss::computeOverlap(kLabels, one_extra), 0.75).found_objects, 1u);
  EXPECT_EQ(ss::countMatches(ss::computeOverlap(kLabels, one_extra), 0.9).found_objects, 0u);
}

TEST(EvaluationMetric, ObjectsAreDistinctNonZeroLabels) {
  const std::vector<int> labels = {7, 0, 3, 7, 3, 0};
  const ss::SceneOverlap overlap = ss::computeOverlap(labels, Segments{});
  EXPECT_EQ(overlap.object_labels, (std::vector<int>{3, 7}));
}

TEST(EvaluationMetric, DuplicateIndicesCountOnce) {
  EXPECT_DOUBLE_EQ(ss::computeOverlap(kLabels, {{2, 2, 3, 3, 4, 5}}).object_best_iou[0], 1.0);
}

TEST(EvaluationMetric, OutOfRangeIndexIsAnInputError) {
  EXPECT_THROW(ss::computeOverlap(kLabels, Segments{{2, 10}}), ss::InputError);
  EXPECT_THROW(ss::computeOverlap(kLabels, Segments{{-1}}), ss::InputError);
}

TEST(EvaluationMetric, PoolingSumsCountsRatherThanAveragingScenes) {
  // Scene A: 1 object, 1 perfect segment -> P 1, R 1.
  // Scene B: 3 objects, 1 perfect segment + 1 spurious -> P 1/2, R 1/3.
  const std::vector<int> labels_b = {1, 1, 2, 2, 3, 3, 0, 0};
  ss::MatchCounts pooled = ss::countMatches(ss::computeOverlap({1, 1}, {{0, 1}}), 0.5);
  pooled += ss::countMatches(ss::computeOverlap(labels_b, {{0, 1}, {6, 7}}), 0.5);
  EXPECT_EQ(pooled.segments, 3u);
  EXPECT_EQ(pooled.correct_segments, 2u);
  EXPECT_EQ(pooled.objects, 4u);
  EXPECT_EQ(pooled.found_objects, 2u);

  const ss::Metrics m = ss::computeMetrics(pooled);
  EXPECT_DOUBLE_EQ(m.precision, 2.0 / 3.0);  // averaged per scene would be 3/4
  EXPECT_DOUBLE_EQ(m.recall, 2.0 / 4.0);     // averaged per scene would be 2/3
  EXPECT_DOUBLE_EQ(m.f, 2.0 * (2.0 / 3.0) * 0.5 / (2.0 / 3.0 + 0.5));
  EXPECT_DOUBLE_EQ(m.mean_best_iou, 2.0 / 4.0);
}

TEST(EvaluationMetric, SegmentOverloadMatchesIndexSets) {
  ss::Segment segment;
  segment.indices = {6, 7, 8};
  const ss::SceneOverlap overlap = ss::computeOverlap(kLabels, std::vector<ss::Segment>{segment});
  EXPECT_DOUBLE_EQ(overlap.segment_best_iou[0], 0.75);
}
