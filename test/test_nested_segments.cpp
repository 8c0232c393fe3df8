// Stage nested: foreign objects taken out of a larger segment.
#include <gtest/gtest.h>

#include <numeric>

#include "fake_evidence.h"
#include "symmetry_segmentation/symmetry/nested_segments.h"

namespace ss = symmetry_segmentation;

namespace {

ss::CandidateSegment segment(int first, int last, float plane_id) {
  ss::CandidateSegment s;
  s.points.resize(last - first + 1);
  std::iota(s.points.begin(), s.points.end(), first);
  s.plane.normal = Eigen::Vector3f::UnitX();
  s.plane.distance = plane_id;
  return s;
}

// The plane with id 1 explains points below 60 only (its own object); the plane with id 2
// explains everything.
bool explainedBelow60(int index, const ss::SymmetryPlane& plane) { return plane.distance == 2.0f || index < 60; }

/// Evidence over 100 points whose reflections land (on the point itself) where explainedBelow60.
test_support::FakeEvidence explainedBelow60Evidence() {
  test_support::FakeEvidence evidence(100);
  evidence.lands_on = [](int index, const ss::SymmetryPlane& plane) { return explainedBelow60(index, plane) ? index : -1; };
  return evidence;
}

}  // namespace

TEST(NestedSegments, ANestedObjectTheOuterPlaneDoesNotExplainIsTakenOut) {
  std::vector<ss::CandidateSegment> segments = {segment(0, 99, 1.0f), segment(60, 89, 3.0f)};
  const auto changed = ss::removeForeignParts(segments, explainedBelow60Evidence(), 10, {});
  ASSERT_EQ(changed, std::vector<std::size_t>{0});
  std::vector<int> expected(60);
  std::iota(expected.begin(), expected.end(), 0);
  for (int i = 90; i < 100; ++i) expected.push_back(i);
  EXPECT_EQ(segments[0].points, expected);
  EXPECT_EQ(segments[1].points.size(), 30u) << "the nested object itself is untouched";
}

TEST(NestedSegments, APartTheOuterPlaneExplainsStays) {
  std::vector<ss::CandidateSegment> segments = {segment(0, 99, 2.0f), segment(60, 89, 3.0f)};
  EXPECT_TRUE(ss::removeForeignParts(segments, explainedBelow60Evidence(), 10, {}).empty());
  EXPECT_EQ(segments[0].points.size(), 100u);
}

TEST(NestedSegments, OnlyNestedAndClearlySmallerSegmentsCount) {
  // Half outside: an overlapping neighbour, not a nested one.
  std::vector<ss::CandidateSegment> overlapping = {segment(0, 99, 1.0f), segment(80, 139, 3.0f)};
  EXPECT_TRUE(ss::removeForeignParts(overlapping, explainedBelow60Evidence(), 10, {}).empty());
  // Nearly as large as the outer segment: the same object found twice (deduplication's job).
  std::vector<ss::CandidateSegment> twin = {segment(0, 99, 1.0f), segment(5, 94, 3.0f)};
  EXPECT_TRUE(ss::removeForeignParts(twin, explainedBelow60Evidence(), 10, {}).empty());
}

TEST(NestedSegments, TooLittleLeftEmptiesTheOuterSegment) {
  std::vector<ss::CandidateSegment> segments = {segment(50, 99, 1.0f), segment(60, 97, 3.0f)};
  const auto changed = ss::removeForeignParts(segments, explainedBelow60Evidence(), 20, {});
  ASSERT_EQ(changed, std::vector<std::size_t>{0});
  EXPECT_TRUE(segments[0].points.empty()) << "12 points left, fewer than 20";
}
