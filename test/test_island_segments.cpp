// Stages islands and island_segments: islands (points apart from all others), and those one
// found plane explains whole.
#include <gtest/gtest.h>

#include <numeric>

#include "fake_evidence.h"
#include "symmetry_segmentation/symmetry/island_segments.h"
#include "symmetry_segmentation/symmetry/islands.h"

namespace ss = symmetry_segmentation;

namespace {

// Two rows of points 1 cm apart: x in [0, 0.1) and x in [0.2, 0.25), 5 cm gap between them.
ss::Cloud::Ptr twoRows() {
  auto cloud = std::make_shared<ss::Cloud>();
  for (int i = 0; i < 10; ++i) {
    ss::PointT p;
    p.x = 0.01f * i;
    p.y = p.z = 0.0f;
    cloud->push_back(p);
  }
  for (int i = 0; i < 5; ++i) {
    ss::PointT p;
    p.x = 0.2f + 0.01f * i;
    p.y = p.z = 0.0f;
    cloud->push_back(p);
  }
  return cloud;
}

std::vector<int> range(int first, int last) {
  std::vector<int> r(last - first + 1);
  std::iota(r.begin(), r.end(), first);
  return r;
}

ss::CandidateSegment segmentWithPlane(std::vector<int> points, float plane_id) {
  ss::CandidateSegment s;
  s.points = std::move(points);
  s.plane.normal = Eigen::Vector3f::UnitX();
  s.plane.distance = plane_id;
  return s;
}

// The plane with distance 1 explains anything; distance 2 only what has at most 6 points;
// distance 3 sends a twentieth of anything into free space.
ss::SegmentScores scoreByPlane(const std::vector<int>& points, const ss::SymmetryPlane& plane) {
  ss::SegmentScores scores;
  scores.occlusion = plane.distance == 1.0f || points.size() <= 6 ? 1.0f : plane.distance == 3.0f ? 0.95f : 0.5f;
  scores.smoothness = 0.0f;
  return scores;
}

/// Evidence over the two rows that scores by plane (scoreByPlane).
test_support::FakeEvidence scoredByPlane() {
  test_support::FakeEvidence evidence(*twoRows());
  evidence.score = scoreByPlane;
  return evidence;
}

ss::SymmetryFilterParams filter() {
  ss::SymmetryFilterParams params;
  params.s_occl = 0.9f;
  params.s_smooth = 0.05f;
  params.min_segment_points = 3;
  return params;
}

}  // namespace

TEST(IslandSegments, IslandsAreGroupsSeparatedByMoreThanTheGap) {
  const auto islands = ss::spatialIslands(twoRows(), 0.015f, 1);
  ASSERT_EQ(islands.size(), 2u);
  EXPECT_EQ(islands[0], range(0, 9));
  EXPECT_EQ(islands[1], range(10, 14));
  EXPECT_EQ(ss::spatialIslands(twoRows(), 0.015f, 6).size(), 1u) << "the 5-point island is too small";
  EXPECT_EQ(ss::spatialIslands(twoRows(), 0.2f, 1).size(), 1u) << "a gap wider than 5 cm joins them";
  EXPECT_TRUE(ss::spatialIslands(std::make_shared<ss::Cloud>(), 0.015f, 1).empty());
}

TEST(IslandSegments, AnIslandIsProposedWithThePlaneThatExplainsItWhole) {
  const std::vector<std::vector<int>> islands = {range(0, 9), range(10, 14)};
  // A piece of the first island with a plane that explains only the piece, another with a plane
  // that explains the whole island; nothing lies on the second island.
  const std::vector<ss::CandidateSegment> segments = {segmentWithPlane(range(0, 5), 2.0f),
                                                      segmentWithPlane(range(4, 9), 1.0f)};
  const auto proposed = ss::explainedIslands(islands, segments, {}, scoredByPlane(), filter(), {});
  ASSERT_EQ(proposed.size(), 1u);
  EXPECT_EQ(proposed[0].points, range(0, 9));
  EXPECT_EQ(proposed[0].plane.distance, 1.0f);
  EXPECT_FLOAT_EQ(proposed[0].scores.occlusion, 1.0f);
}

TEST(IslandSegments, AnIslandNoPlaneExplainsIsNotProposed) {
  const std::vector<std::vector<int>> islands = {range(0, 9)};
  // Only the piece's plane, which fails on the whole island; and a segment mostly elsewhere
  // (its plane would explain anything) does not lend its plane.
  const std::vector<ss::CandidateSegment> segments = {segmentWithPlane(range(0, 5), 2.0f),
                                                      segmentWithPlane(range(8, 14), 1.0f)};
  ss::IslandSegmentParams no_relief;  // an island alone asks what the filter asks
  no_relief.alone_free_factor = 1.0f;
  EXPECT_TRUE(ss::explainedIslands(islands, segments, {}, scoredByPlane(), filter(), no_relief).empty());
}

TEST(IslandSegments, AnIslandNothingElseCoversNeedsLessOfItsPlane) {
  const std::vector<std::vector<int>> islands = {range(0, 9)};
  ss::SymmetryFilterParams strict = filter();
  strict.s_occl = 0.99f;
  const ss::IslandSegmentParams params;  // alone_free_factor 10: occlusion above 0.9
  // Its only plane sends a twentieth of it into free space: short of the filter, but nothing
  // else accounts for the island.
  const std::vector<ss::CandidateSegment> slightly_off = {segmentWithPlane(range(0, 9), 3.0f)};
  const auto alone = ss::explainedIslands(islands, slightly_off, {}, scoredByPlane(), strict, params);
  ASSERT_EQ(alone.size(), 1u);
  EXPECT_EQ(alone[0].points, range(0, 9));
  EXPECT_FLOAT_EQ(alone[0].scores.occlusion, 0.95f);
  // The allowance scales with the filter's: one that keeps nothing keeps no island either.
  ss::SymmetryFilterParams keeps_nothing = strict;
  keeps_nothing.s_occl = 1.0f;
  EXPECT_TRUE(ss::explainedIslands(islands, slightly_off, {}, scoredByPlane(), keeps_nothing, params).empty());
  // A reported segment covering half of it already accounts for it.
  const std::vector<ss::CandidateSegment> reported = {segmentWithPlane(range(0, 4), 1.0f)};
  EXPECT_TRUE(ss::explainedIslands(islands, slightly_off, reported, scoredByPlane(), strict, params).empty());
  EXPECT_EQ(ss::explainedIslands(islands, slightly_off, {segmentWithPlane(range(0, 3), 1.0f)}, scoredByPlane(),
                                 strict, params).size(),
            1u)
      << "four of ten points is less than half";
  // A plane that sends half of it into free space says it is no object, covered or not.
  const std::vector<ss::CandidateSegment> contradicted = {segmentWithPlane(range(0, 9), 2.0f)};
  EXPECT_TRUE(ss::explainedIslands(islands, contradicted, {}, scoredByPlane(), strict, params).empty());
}
