// Stage composites: a segment made of two objects meeting at a concave seam is replaced by the two.
#include <gtest/gtest.h>

#include <numeric>

#include "fake_evidence.h"
#include "symmetry_segmentation/symmetry/composite_segments.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"

namespace ss = symmetry_segmentation;

namespace {

// Points 0..99 on a line, each linked to its two neighbours. Object A is 0..59, object B 60..99:
// their seam is the link (59, 60).
constexpr int kPoints = 100;
constexpr int kSeam = 60;

std::vector<std::vector<int>> chainNeighbours() {
  std::vector<std::vector<int>> neighbours(kPoints);
  for (int i = 0; i < kPoints; ++i) {
    if (i > 0) neighbours[i].push_back(i - 1);
    if (i + 1 < kPoints) neighbours[i].push_back(i + 1);
  }
  return neighbours;
}

// The chain plus a corner 100..109 in neither object, linked to A at 55 and to B at 65: a path
// from A to B that avoids the seam.
std::vector<std::vector<int>> chainWithCorner() {
  std::vector<std::vector<int>> neighbours = chainNeighbours();
  neighbours.resize(kPoints + 10);
  for (int i = kPoints; i < kPoints + 10; ++i) {
    if (i > kPoints) neighbours[i].push_back(i - 1);
    if (i + 1 < kPoints + 10) neighbours[i].push_back(i + 1);
  }
  neighbours[55].push_back(kPoints);
  neighbours[kPoints].push_back(55);
  neighbours[kPoints + 9].push_back(65);
  neighbours[65].push_back(kPoints + 9);
  return neighbours;
}

ss::CandidateSegment segment(int first, int last, float plane_id = 0.0f) {
  ss::CandidateSegment s;
  s.points.resize(last - first + 1);
  std::iota(s.points.begin(), s.points.end(), first);
  s.plane.normal = Eigen::Vector3f::UnitX();
  s.plane.distance = plane_id;
  return s;
}

// Scores a rest segment gets: occlusion 0.5 marks them.
ss::SegmentScores markedScores(const std::vector<int>&, const ss::SymmetryPlane&) {
  ss::SegmentScores scores;
  scores.occlusion = 0.5f;
  return scores;
}

bool creaseAtSeam(int a, int b) { return std::min(a, b) == kSeam - 1 && std::max(a, b) == kSeam; }
bool noCrease(int, int) { return false; }

// Each point reflects onto a point of its own object (the plane is a symmetry of each).
int mirrorWithinObject(int index, const ss::SymmetryPlane&) {
  return index < kSeam ? (kSeam - 1 - index) : (kSeam + kPoints - 1 - index);
}
// One object's reflection lands on the other (mirror halves of one object).
int mirrorAcrossSeam(int index, const ss::SymmetryPlane&) {
  const int mirrored = kPoints - 1 - index;
  return mirrored;
}

/// Evidence over the chain (or other links) with the test's creases and reflections; rest
/// segments score occlusion 0.5.
template <typename Crease, typename Match>
test_support::FakeEvidence evidence(std::vector<std::vector<int>> links, Crease crease, Match lands_on) {
  const std::size_t points = links.size();
  test_support::FakeEvidence result(points, std::move(links));
  result.crease = crease;
  result.lands_on = lands_on;
  result.score = markedScores;
  return result;
}

}  // namespace

TEST(CompositeSegments, TwoObjectsMeetingAtACreaseReplaceTheirUnion) {
  std::vector<ss::CandidateSegment> segments = {segment(0, 99, 1.0f), segment(0, 59, 2.0f)};
  const std::vector<ss::CandidateSegment> parts = {segment(0, 99, 1.0f), segment(0, 59, 2.0f), segment(60, 99, 3.0f)};
  ss::CompositeSegmentParams params;
  params.min_seam_links = 1;
  EXPECT_EQ(ss::splitCompositeSegments(segments, parts, evidence(chainNeighbours(), creaseAtSeam, mirrorWithinObject), params), 1u);
  ASSERT_EQ(segments.size(), 2u) << "the union is gone; A, already present, is not added twice";
  EXPECT_EQ(segments[0].points, segment(0, 59).points);
  EXPECT_EQ(segments[1].points, segment(60, 99).points);
  EXPECT_EQ(segments[1].plane.distance, 3.0f) << "each part keeps its own plane";
}

TEST(CompositeSegments, AFlatOrConvexSeamKeepsTheSegmentWhole) {
  std::vector<ss::CandidateSegment> segments = {segment(0, 99)};
  const std::vector<ss::CandidateSegment> parts = {segment(0, 59), segment(60, 99)};
  ss::CompositeSegmentParams params;
  params.min_seam_links = 1;
  EXPECT_EQ(ss::splitCompositeSegments(segments, parts, evidence(chainNeighbours(), noCrease, mirrorWithinObject), params), 0u);
  ASSERT_EQ(segments.size(), 1u);
  EXPECT_EQ(segments[0].points.size(), 100u);
}

TEST(CompositeSegments, MirrorHalvesOfOneObjectStayTogether) {
  // 50/50 so that the halves map onto each other exactly.
  std::vector<ss::CandidateSegment> segments = {segment(0, 99)};
  const std::vector<ss::CandidateSegment> parts = {segment(0, 49), segment(50, 99)};
  const auto creaseInMiddle = [](int a, int b) { return std::min(a, b) == 49 && std::max(a, b) == 50; };
  ss::CompositeSegmentParams params;
  params.min_seam_links = 1;
  EXPECT_EQ(ss::splitCompositeSegments(segments, parts, evidence(chainNeighbours(), creaseInMiddle, mirrorAcrossSeam), params), 0u);
  EXPECT_EQ(segments.size(), 1u);
  // The same parts under a plane that maps each onto itself are two objects.
  const auto mirrorWithinHalves = [](int index, const ss::SymmetryPlane&) { return index < 50 ? 49 - index : 149 - index; };
  EXPECT_EQ(ss::splitCompositeSegments(segments, parts, evidence(chainNeighbours(), creaseInMiddle, mirrorWithinHalves), params), 1u);
  EXPECT_EQ(segments.size(), 2u);
}

TEST(CompositeSegments, PartsMustCoverTheSegmentAndBeSubstantial) {
  ss::CompositeSegmentParams params;
  params.min_seam_links = 1;
  // Together only 70 of 100 points: a third object (or more) is in the segment.
  std::vector<ss::CandidateSegment> uncovered = {segment(0, 99)};
  EXPECT_EQ(ss::splitCompositeSegments(uncovered, {segment(0, 34), segment(60, 94)}, evidence(chainNeighbours(), creaseAtSeam, mirrorWithinObject), params),
            0u);
  // A sliver (10 of 100 points) is a detail of the object, not a second object.
  std::vector<ss::CandidateSegment> sliver = {segment(0, 99)};
  const auto creaseAt90 = [](int a, int b) { return std::min(a, b) == 89 && std::max(a, b) == 90; };
  EXPECT_EQ(ss::splitCompositeSegments(sliver, {segment(0, 89), segment(90, 99)}, evidence(chainNeighbours(), creaseAt90, mirrorWithinObject), params),
            0u);
  // Largely overlapping parts are the same object found twice.
  std::vector<ss::CandidateSegment> overlapping = {segment(0, 99)};
  EXPECT_EQ(ss::splitCompositeSegments(overlapping, {segment(0, 69), segment(40, 99)}, evidence(chainNeighbours(), creaseAtSeam, mirrorWithinObject), params),
            0u);
  EXPECT_EQ(overlapping.size(), 1u);
}

TEST(CompositeSegments, PartsThatDoNotTouchAreTwoObjects) {
  // Linked by one link only (five make a seam by default), and that link is not creased.
  std::vector<ss::CandidateSegment> segments = {segment(0, 99)};
  EXPECT_EQ(ss::splitCompositeSegments(segments, {segment(0, 59), segment(60, 99)}, evidence(chainNeighbours(), noCrease, mirrorWithinObject), ss::CompositeSegmentParams{}),
            1u);
  EXPECT_EQ(segments.size(), 2u);
}

TEST(CompositeSegments, TheRestOfOneObjectFoundAloneIsTheOtherWhenApartOrMetAtCreasesOnly) {
  // Only A (0..59) is found alone; the rest (60..99) is hardly linked to it.
  std::vector<ss::CandidateSegment> segments = {segment(0, 99, 1.0f)};
  EXPECT_EQ(ss::splitCompositeSegments(segments, {segment(0, 59, 2.0f)}, evidence(chainNeighbours(), noCrease, mirrorWithinObject), ss::CompositeSegmentParams{}),
            1u);
  ASSERT_EQ(segments.size(), 2u);
  EXPECT_EQ(segments[0].points, segment(0, 59).points);
  EXPECT_EQ(segments[1].points, segment(60, 99).points);
  EXPECT_EQ(segments[1].plane.distance, 1.0f) << "the rest keeps the larger segment's plane";
  EXPECT_EQ(segments[1].scores.occlusion, 0.5f) << "and is scored for it";

  // Meeting A at creases only (no face running on across the seam): still two objects.
  ss::CompositeSegmentParams params;
  params.min_seam_links = 1;
  std::vector<ss::CandidateSegment> creased = {segment(0, 99, 1.0f)};
  EXPECT_EQ(ss::splitCompositeSegments(creased, {segment(0, 59, 2.0f)}, evidence(chainNeighbours(), creaseAtSeam, mirrorWithinObject), params),
            1u);
  // A flat link across the seam as well (a flush face): the rest may be the part's own, kept
  // whole; and even with both parts found alone, a face running on across the seam makes them
  // one object.
  auto flush = chainNeighbours();
  flush[58].push_back(61);
  flush[61].push_back(58);
  std::vector<ss::CandidateSegment> one_body = {segment(0, 99, 1.0f)};
  EXPECT_EQ(ss::splitCompositeSegments(one_body, {segment(0, 59, 2.0f)}, evidence(flush, creaseAtSeam, mirrorWithinObject), params),
            0u);
  EXPECT_EQ(one_body.size(), 1u);
  EXPECT_EQ(ss::splitCompositeSegments(one_body, {segment(0, 59, 2.0f), segment(60, 99, 3.0f)}, evidence(flush, creaseAtSeam, mirrorWithinObject), params),
            0u);
}

// An object seen in two pieces either side of another standing in front of it, both centred on
// one plane (a box behind a board): the cut of that plane takes all three. The pieces (0..29,
// 70..99) are found alone and mirror onto each other; the occluder (30..69) is not.
TEST(CompositeSegments, PiecesMirroredOntoEachOtherAroundTheRestAreOneObject) {
  auto pieces_and_occluder = [] { return std::vector<ss::CandidateSegment>{segment(0, 99, 1.0f)}; };
  const std::vector<ss::CandidateSegment> pieces = {segment(0, 29, 2.0f), segment(70, 99, 3.0f)};
  std::vector<ss::CandidateSegment> segments = pieces_and_occluder();
  EXPECT_EQ(ss::splitCompositeSegments(segments, pieces, evidence(chainNeighbours(), noCrease, mirrorAcrossSeam),
                                       ss::CompositeSegmentParams{}),
            1u);
  ASSERT_EQ(segments.size(), 2u);
  std::vector<int> both_pieces = segment(0, 29).points;
  const std::vector<int> right = segment(70, 99).points;
  both_pieces.insert(both_pieces.end(), right.begin(), right.end());
  EXPECT_EQ(segments[0].points, both_pieces) << "the pieces are one object";
  EXPECT_EQ(segments[1].points, segment(30, 69).points) << "the occluder the other";
  for (const auto& split : segments) {
    EXPECT_EQ(split.plane.distance, 1.0f) << "both keep the union's plane";
    EXPECT_EQ(split.scores.occlusion, 0.5f) << "and are scored for it";
  }

  // Pieces joined to the occluder by a flat face running on (not apart, no crease) stay whole.
  std::vector<ss::CandidateSegment> unchanged = pieces_and_occluder();
  ss::CompositeSegmentParams params;
  params.min_seam_links = 1;
  EXPECT_EQ(ss::splitCompositeSegments(unchanged, pieces, evidence(chainNeighbours(), noCrease, mirrorAcrossSeam), params),
            0u);
  EXPECT_EQ(unchanged.size(), 1u);
}

// Two parts that each have a symmetry of their own but run on into each other without a crease
// (an L-shaped block's slab and upright, joined through the corner under the upright that
// neither part took) are one object; the same parts joined only across creases are two.
TEST(CompositeSegments, PartsJoinedWithoutACreaseThroughTheRestStayOneObject) {
  const std::vector<std::vector<int>> neighbours = chainWithCorner();
  const ss::CandidateSegment whole = segment(0, kPoints + 9, 1.0f);
  const std::vector<ss::CandidateSegment> parts = {segment(0, 59, 2.0f), segment(60, 99, 3.0f)};
  ss::CompositeSegmentParams params;
  params.min_seam_links = 1;

  std::vector<ss::CandidateSegment> segments = {whole};
  EXPECT_EQ(ss::splitCompositeSegments(segments, parts, evidence(neighbours, creaseAtSeam, mirrorWithinObject), params), 0u);
  ASSERT_EQ(segments.size(), 1u);
  EXPECT_EQ(segments[0].points.size(), 110u);

  // The corner meets B at a crease too: every path from A to B crosses one.
  const auto creases = [](int a, int b) {
    return creaseAtSeam(a, b) || (std::min(a, b) == 65 && std::max(a, b) == kPoints + 9);
  };
  segments = {whole};
  EXPECT_EQ(ss::splitCompositeSegments(segments, parts, evidence(neighbours, creases, mirrorWithinObject), params), 1u);
  ASSERT_EQ(segments.size(), 2u);
  EXPECT_EQ(segments[0].points, segment(0, 59).points);
  EXPECT_EQ(segments[1].points, segment(60, 99).points);
}

TEST(CompositeSegments, TheStageTakesPartsFromCandidatesTheFilterDidNotKeep) {
  // Neither object passed the filter alone; their union did. The cuts still found each.
  ss::PipelineState state;
  state.evidence = std::make_unique<test_support::FakeEvidence>(evidence(chainNeighbours(), creaseAtSeam, mirrorWithinObject));
  state.segments = {segment(0, 99, 1.0f)};
  state.candidates = {segment(0, 99, 1.0f), segment(0, 59, 2.0f), segment(60, 99, 3.0f)};
  ss::CompositeSegmentParams params;
  params.min_seam_links = 1;
  ss::CompositeStage(params).run(state);
  ASSERT_EQ(state.segments.size(), 2u);
  EXPECT_EQ(state.segments[0].points, segment(0, 59).points);
  EXPECT_EQ(state.segments[1].points, segment(60, 99).points);
}

// Normals smoothed over a few centimetres turn through the concave corner where a box stands on
// another in steps of ~15 deg per 1 cm link: no link there is a crease at crease_angle_deg, yet
// the corner is no face running on. A path over such links does not make the boxes one body;
// one over a flat face (steps of a few degrees) still does.
TEST(CompositeSegments, APathThroughASmoothedConcaveCornerDoesNotJoinTheParts) {
  const std::vector<std::vector<int>> neighbours = chainWithCorner();
  const auto onCorner = [](int a, int b) { return std::max(a, b) >= kPoints; };
  // Every corner link concave, its normals `turn` degrees apart; the seam (59, 60) a sharp crease.
  const auto corner_turning = [&](float turn) {
    auto result = evidence(neighbours, noCrease, mirrorWithinObject);
    result.crease_at_angle = [onCorner, turn](int a, int b, float angle_deg) {
      return creaseAtSeam(a, b) || (onCorner(a, b) && turn > angle_deg);
    };
    return result;
  };
  const ss::CandidateSegment whole = segment(0, kPoints + 9, 1.0f);
  const std::vector<ss::CandidateSegment> parts = {segment(0, 59, 2.0f), segment(60, 99, 3.0f)};
  ss::CompositeSegmentParams params;
  params.min_seam_links = 1;

  std::vector<ss::CandidateSegment> segments = {whole};
  EXPECT_EQ(ss::splitCompositeSegments(segments, parts, corner_turning(15.0f), params), 1u)
      << "a corner turning 15 deg per link is a seam";
  EXPECT_EQ(segments.size(), 2u);

  segments = {whole};
  EXPECT_EQ(ss::splitCompositeSegments(segments, parts, corner_turning(4.0f), params), 0u)
      << "a face turning 4 deg per link runs on: one body";
  EXPECT_EQ(segments.size(), 1u);

  // Judged at the crease angle instead, the smoothed corner joins them (what this replaced).
  params.joined_angle_deg = params.crease_angle_deg;
  segments = {whole};
  EXPECT_EQ(ss::splitCompositeSegments(segments, parts, corner_turning(15.0f), params), 0u);
}

// Seen from where the end face of its slab is hidden, an L-shaped block is to the geometry a low
// box against a tall one; only its one colour says it is one object. Two objects of different
// colours still part; a cloud without colour (use_color false) decides on the geometry alone.
TEST(CompositeSegments, PartsOfOneColourAreOneObjectsParts) {
  ss::Cloud cloud(static_cast<uint32_t>(kPoints), 1);
  for (auto& point : cloud) {
    point.r = 200;
    point.g = 40;
    point.b = 40;
  }
  const std::vector<ss::CandidateSegment> parts = {segment(0, 59, 2.0f), segment(60, 99, 3.0f)};
  ss::CompositeSegmentParams params;
  params.min_seam_links = 1;
  params.use_color = true;
  auto split = [&](const ss::Cloud& colored, const ss::CompositeSegmentParams& with) {
    test_support::FakeEvidence scene(colored, chainNeighbours());
    scene.crease = creaseAtSeam;
    scene.lands_on = mirrorWithinObject;
    scene.score = markedScores;
    std::vector<ss::CandidateSegment> segments = {segment(0, 99, 1.0f)};
    return ss::splitCompositeSegments(segments, parts, scene, with);
  };
  EXPECT_EQ(split(cloud, params), 0u) << "one colour: one object";
  ss::CompositeSegmentParams without_color = params;
  without_color.use_color = false;
  EXPECT_EQ(split(cloud, without_color), 1u);
  ss::Cloud two_colors = cloud;
  for (int i = kSeam; i < kPoints; ++i) {
    two_colors[i].r = 40;
    two_colors[i].g = 120;
    two_colors[i].b = 200;
  }
  EXPECT_EQ(split(two_colors, params), 1u) << "two colours: two objects";
  // Nearly one colour (a few CIELAB units: shading, print) is one colour.
  ss::Cloud shaded = cloud;
  for (int i = kSeam; i < kPoints; ++i) shaded[i].r = 203;
  EXPECT_EQ(split(shaded, params), 0u);
}

// One print over both parts: their mean colours differ as much as two objects' do, but they share
// its palette; two prints of other colours share none of it.
TEST(CompositeSegments, PartsOfOnePrintAreOneObjectsParts) {
  ss::Cloud printed(static_cast<uint32_t>(kPoints), 1);
  for (int i = 0; i < kPoints; ++i) {
    // Part a mostly red with yellow patches, part b mostly yellow with red ones.
    const bool red = i < kSeam ? i % 4 != 0 : i % 4 == 0;
    printed[i].r = red ? 200 : 230;
    printed[i].g = red ? 40 : 200;
    printed[i].b = red ? 40 : 20;
  }
  const std::vector<ss::CandidateSegment> parts = {segment(0, 59, 2.0f), segment(60, 99, 3.0f)};
  ss::CompositeSegmentParams params;
  params.min_seam_links = 1;
  params.use_color = true;
  auto split = [&](const ss::Cloud& colored, const ss::CompositeSegmentParams& with) {
    test_support::FakeEvidence scene(colored, chainNeighbours());
    scene.crease = creaseAtSeam;
    scene.lands_on = mirrorWithinObject;
    scene.score = markedScores;
    std::vector<ss::CandidateSegment> segments = {segment(0, 99, 1.0f)};
    return ss::splitCompositeSegments(segments, parts, scene, with);
  };
  EXPECT_EQ(split(printed, params), 0u) << "one print: one object";
  ss::CompositeSegmentParams by_mean_only = params;
  by_mean_only.min_color_overlap = 0.0f;
  EXPECT_EQ(split(printed, by_mean_only), 1u) << "the means alone differ";
  ss::Cloud two_prints = printed;
  for (int i = kSeam; i < kPoints; ++i) {
    const bool blue = i % 4 != 0;
    two_prints[i].r = blue ? 40 : 30;
    two_prints[i].g = blue ? 120 : 200;
    two_prints[i].b = blue ? 200 : 60;
  }
  EXPECT_EQ(split(two_prints, params), 1u) << "two prints: two objects";
}
