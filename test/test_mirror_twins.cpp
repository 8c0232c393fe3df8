// Stage mirror_twins: a segment of two like objects mirrored onto each other is split when the sensor saw
// through the space between them, and stays whole when it did not (one object seen in pieces).
#include <gtest/gtest.h>

#include <numeric>

#include "fake_evidence.h"
#include "symmetry_segmentation/symmetry/mirror_twins.h"

namespace ss = symmetry_segmentation;

namespace {

// Points 0..9 on x in [-0.2, -0.11] and 10..19 on x in [0.11, 0.2]: two pieces, each a chain of
// neighbours, none linking the pieces; the plane x = 0 mirrors i onto 19 - i.
ss::Cloud twoPieces() {
  ss::Cloud cloud;
  for (int i = 0; i < 20; ++i) {
    ss::PointT p;
    p.x = i < 10 ? -0.2f + 0.01f * i : 0.11f + 0.01f * (i - 10);
    p.y = p.z = 0.0f;
    cloud.push_back(p);
  }
  return cloud;
}

std::vector<std::vector<int>> chains() {
  std::vector<std::vector<int>> neighbours(20);
  for (int i = 0; i < 20; ++i) {
    if (i != 0 && i != 10) neighbours[i].push_back(i - 1);
    if (i != 9 && i != 19) neighbours[i].push_back(i + 1);
  }
  return neighbours;
}

ss::CandidateSegment wholeSegment() {
  ss::CandidateSegment segment;
  segment.points.resize(20);
  std::iota(segment.points.begin(), segment.points.end(), 0);
  segment.plane.normal = Eigen::Vector3f::UnitX();
  segment.plane.distance = 0.0f;
  return segment;
}

int acrossThePlane(int index, const ss::SymmetryPlane&) { return 19 - index; }
int withinEachPiece(int index, const ss::SymmetryPlane&) { return index < 10 ? 9 - index : 29 - index; }
bool seenThrough(const Eigen::Vector3f&) { return true; }
bool hidden(const Eigen::Vector3f&) { return false; }
ss::SegmentScores unitScores(const std::vector<int>&, const ss::SymmetryPlane&) {
  ss::SegmentScores scores;
  scores.occlusion = 1.0f;
  return scores;
}

test_support::FakeEvidence evidence(std::vector<std::vector<int>> links, int (*lands_on)(int, const ss::SymmetryPlane&),
                                    bool (*free)(const Eigen::Vector3f&)) {
  test_support::FakeEvidence result(twoPieces(), std::move(links));
  result.lands_on = lands_on;
  result.free = free;
  result.score = unitScores;
  return result;
}

}  // namespace

TEST(MirrorTwins, PiecesMirroredAcrossObservedFreeSpaceAreTwoObjects) {
  std::vector<ss::CandidateSegment> segments = {wholeSegment()};
  ss::MirrorTwinParams params;
  params.min_pairs = 5;
  EXPECT_EQ(ss::splitMirrorTwins(segments, evidence(chains(), acrossThePlane, seenThrough), params), 1u);
  ASSERT_EQ(segments.size(), 2u);
  EXPECT_EQ(segments[0].points, std::vector<int>({0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(segments[1].points, std::vector<int>({10, 11, 12, 13, 14, 15, 16, 17, 18, 19}));
  EXPECT_FLOAT_EQ(segments[1].scores.occlusion, 1.0f) << "each piece is scored";
}

TEST(MirrorTwins, PiecesOfOneObjectSeenAroundSomethingStayWhole) {
  // Between the pieces the sensor saw nothing (an occluder in front, the object's inside).
  std::vector<ss::CandidateSegment> segments = {wholeSegment()};
  ss::MirrorTwinParams params;
  params.min_pairs = 5;
  EXPECT_EQ(ss::splitMirrorTwins(segments, evidence(chains(), acrossThePlane, hidden), params), 0u);
  EXPECT_EQ(segments.size(), 1u);
  // Each piece mirrored onto itself (a handle apart from its mug's body): no pair across.
  EXPECT_EQ(ss::splitMirrorTwins(segments, evidence(chains(), withinEachPiece, seenThrough), params), 0u);
  // One connected piece: nothing to split.
  auto linked = chains();
  linked[9].push_back(10);
  linked[10].push_back(9);
  EXPECT_EQ(ss::splitMirrorTwins(segments, evidence(linked, acrossThePlane, seenThrough), params), 0u);
  // Too few pairs across to decide.
  params.min_pairs = 50;
  EXPECT_EQ(ss::splitMirrorTwins(segments, evidence(chains(), acrossThePlane, seenThrough), params), 0u);
  EXPECT_EQ(segments.size(), 1u);
}

TEST(MirrorTwins, AUShapeWhoseBaseMirrorsOntoItselfStaysWhole) {
  // A U lying open to the sensor: one upright (points 0-3) apart from the base and the other
  // upright (4-19) over the links, the free space between the uprights seen through. The uprights
  // mirror onto each other, but the base mirrors onto itself: one object's plane, not the plane
  // between two.
  std::vector<std::vector<int>> links(20);
  for (int i = 0; i < 20; ++i) {
    if (i != 0 && i != 4) links[i].push_back(i - 1);
    if (i != 3 && i != 19) links[i].push_back(i + 1);
  }
  ss::MirrorTwinParams params;
  params.min_pairs = 5;
  params.min_part_fraction = 0.15f;
  std::vector<ss::CandidateSegment> segments = {wholeSegment()};
  EXPECT_EQ(ss::splitMirrorTwins(segments, evidence(links, acrossThePlane, seenThrough), params), 0u);
  EXPECT_EQ(segments.size(), 1u);
}
