#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "symmetry_segmentation/parallel_for.h"
#include "fake_evidence.h"
#include "symmetry_segmentation/symmetry/duplicate_segments.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"

namespace ss = symmetry_segmentation;

namespace {

ss::CandidateSegment candidate(int begin, int end, float occlusion, float smoothness) {
  ss::CandidateSegment segment;
  for (int i = begin; i < end; ++i) segment.points.push_back(i);
  segment.scores = ss::SegmentScores{occlusion, smoothness};
  return segment;
}

}  // namespace

TEST(SegmentFilter, ThresholdsAreStrict) {
  ss::SymmetryFilterParams params;
  params.s_occl = 0.9f;
  params.s_smooth = 0.05f;
  params.min_segment_points = 10;
  EXPECT_TRUE(ss::passesFilter(candidate(0, 10, 0.95f, 0.01f), params));
  EXPECT_FALSE(ss::passesFilter(candidate(0, 9, 0.95f, 0.01f), params));   // too small
  EXPECT_FALSE(ss::passesFilter(candidate(0, 10, 0.9f, 0.01f), params));   // occlusion not above
  EXPECT_FALSE(ss::passesFilter(candidate(0, 10, 0.95f, 0.05f), params));  // smoothness not below
}

namespace {

// Evidence whose occlusion score peaks at the plane offset +4 mm (1.0 there, 0.01 less per mm).
test_support::FakeEvidence offsetSensitiveEvidence() {
  test_support::FakeEvidence evidence(100);
  evidence.score = [](const std::vector<int>&, const ss::SymmetryPlane& plane) {
    return ss::SegmentScores{1.0f - 10.0f * std::fabs(plane.distance - 0.004f), 0.0f};
  };
  return evidence;
}

}  // namespace

TEST(SegmentFilter, PlaneOffsetFitFindsTheOffsetThatExplainsTheReflections) {
  const test_support::FakeEvidence evidence = offsetSensitiveEvidence();
  ss::CandidateSegment segment = candidate(0, 50, 0.96f, 0.0f);  // plane at offset 0
  ss::fitPlaneOffset(segment, evidence, 0.006f);
  EXPECT_NEAR(segment.plane.distance, 0.004f, 1e-6f);
  EXPECT_NEAR(segment.scores.occlusion, 1.0f, 1e-5f);
  EXPECT_EQ(segment.points.size(), 50u);

  ss::CandidateSegment near_only = candidate(0, 50, 0.96f, 0.0f);
  ss::fitPlaneOffset(near_only, evidence, 0.002f);  // one step each way
  EXPECT_NEAR(near_only.plane.distance, 0.002f, 1e-6f);

  ss::CandidateSegment best_already = candidate(0, 50, 1.0f, 0.0f);
  best_already.plane.distance = 0.004f;
  ss::fitPlaneOffset(best_already, evidence, 0.006f);
  EXPECT_FLOAT_EQ(best_already.plane.distance, 0.004f);
}

// The stage refits only candidates that fail on occlusion alone; 0 switches it off.
TEST(SegmentFilter, TheStageRefitsCandidatesFailingOnlyOnOcclusion) {
  for (const float reach : {0.006f, 0.0f}) {
    ss::PipelineState state;
    state.evidence = std::make_unique<test_support::FakeEvidence>(offsetSensitiveEvidence());
    state.candidates = {candidate(0, 50, 0.96f, 0.0f),     // plane 4 mm off
                        candidate(50, 100, 0.96f, 0.5f)};  // a smooth boundary: no offset helps
    ss::SymmetryFilterParams params;
    params.plane_offset_search = reach;
    ss::FilterStage(params).run(state);
    if (reach > 0.0f) {
      ASSERT_EQ(state.segments.size(), 1u);
      EXPECT_EQ(state.segments[0].points.front(), 0);
      EXPECT_NEAR(state.segments[0].plane.distance, 0.004f, 1e-6f);
    } else {
      EXPECT_TRUE(state.segments.empty());
    }
    EXPECT_FLOAT_EQ(state.candidates[1].plane.distance, 0.0f);
    EXPECT_FLOAT_EQ(state.candidates[1].scores.occlusion, 0.96f);
  }
}

TEST(SegmentFilter, OverlapOfSmaller) {
  EXPECT_FLOAT_EQ(ss::overlapOfSmaller({1, 2, 3, 4}, {3, 4}), 1.0f);
  EXPECT_FLOAT_EQ(ss::overlapOfSmaller({1, 2, 3, 4}, {4, 5, 6, 7}), 0.25f);
  EXPECT_FLOAT_EQ(ss::overlapOfSmaller({}, {1}), 0.0f);
}

TEST(SegmentFilter, DuplicatesKeepTheCleanestBoundary) {
  ss::DuplicateParams params;
  params.max_overlap = 0.7f;
  const auto kept = ss::removeDuplicates(
      {candidate(0, 100, 1.0f, 0.010f),    // object A
       candidate(5, 100, 1.0f, 0.005f),    // object A again, cleaner boundary: wins
       candidate(200, 300, 1.0f, 0.02f),   // object B
       candidate(80, 220, 1.0f, 0.001f)},  // straddles A and B, overlapping each by < 0.7
      params);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[0].points.front(), 80);
  EXPECT_EQ(kept[1].points.front(), 5);
  EXPECT_EQ(kept[2].points.front(), 200);
}

TEST(SegmentFilter, UnionsSharingAnObjectAreNotTwoObjects) {
  // Objects A (0-69), B (70-199), C (200-269); two cuts give the unions A+B and B+C (B is 65 %
  // of each) and a third cut C alone. One segment per object: of the unions only the cleaner
  // stays, and C alone beside it.
  const auto kept = ss::removeDuplicates({candidate(0, 200, 1.0f, 0.004f), candidate(70, 270, 1.0f, 0.006f),
                                          candidate(200, 270, 1.0f, 0.008f)},
                                         ss::DuplicateParams{});
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].points.front(), 0);
  EXPECT_EQ(kept[1].points.front(), 200);
}

TEST(ParallelFor, EveryIndexOnceAndExceptionsPropagate) {
  for (int threads : {1, 2, 4}) {
    std::vector<int> hits(1000, 0);
    ss::parallelFor(hits.size(), threads, [&](std::size_t i) { hits[i] += 1; });
    EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), 1000) << threads;
  }
  EXPECT_THROW(ss::parallelFor(100, 2, [](std::size_t i) { if (i == 37) throw std::runtime_error("x"); }),
               std::runtime_error);
  std::atomic<int> calls{0};
  ss::parallelFor(0, 2, [&](std::size_t) { ++calls; });
  EXPECT_EQ(calls.load(), 0);
}
