// Stages 5d and 5e: a segment of flush objects is split where its colour changes over a flat
// face running across both; colour edges on one object (a lid at the rim, a cap on a neck,
// print) and an object seen in separate pieces leave it whole. A strip of a neighbour's colour
// moves to the neighbour.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>

#include "fake_evidence.h"
#include "symmetry_segmentation/symmetry/color_histogram.h"
#include "symmetry_segmentation/symmetry/color_seams.h"
#include "symmetry_segmentation/symmetry/stray_color_pieces.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace ss = symmetry_segmentation;

namespace {

using Rgb = std::array<std::uint8_t, 3>;
const Rgb kRed{{200, 40, 40}};
const Rgb kBlue{{40, 120, 200}};

struct Box {
  Eigen::Vector3f low, high;
  Rgb color;
  bool contains(const Eigen::Vector3f& p) const {
    return (p.array() >= low.array() - 1e-4f).all() && (p.array() <= high.array() + 1e-4f).all();
  }
};

// The visible surface of resting boxes, sampled every centimetre (cell centres): every face but
// the bottom, without what lies on or in another box (a shared face is no surface).
ss::Cloud boxSurfaces(const std::vector<Box>& boxes) {
  ss::Cloud cloud;
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    const Box& box = boxes[b];
    for (int axis = 0; axis < 3; ++axis) {
      for (int side = 0; side < 2; ++side) {
        if (axis == 2 && side == 0) continue;
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const int nu = static_cast<int>(std::lround((box.high[u] - box.low[u]) / 0.01f));
        const int nv = static_cast<int>(std::lround((box.high[v] - box.low[v]) / 0.01f));
        for (int i = 0; i < nu; ++i) {
          for (int j = 0; j < nv; ++j) {
            Eigen::Vector3f p;
            p[axis] = side ? box.high[axis] : box.low[axis];
            p[u] = box.low[u] + 0.005f + 0.01f * i;
            p[v] = box.low[v] + 0.005f + 0.01f * j;
            bool hidden = false;
            for (std::size_t o = 0; o < boxes.size(); ++o) hidden = hidden || (o != b && boxes[o].contains(p));
            if (hidden) continue;
            ss::PointT point;
            point.getVector3fMap() = p;
            point.getNormalVector3fMap() = Eigen::Vector3f::Unit(axis) * (side ? 1.0f : -1.0f);
            point.r = box.color[0];
            point.g = box.color[1];
            point.b = box.color[2];
            cloud.push_back(point);
          }
        }
      }
    }
  }
  return cloud;
}

std::vector<std::vector<int>> linksWithin(const ss::Cloud& cloud, float radius) {
  std::vector<std::vector<int>> neighbours(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    for (std::size_t j = 0; j < cloud.size(); ++j) {
      if (i != j && (cloud[i].getVector3fMap() - cloud[j].getVector3fMap()).norm() < radius) {
        neighbours[i].push_back(static_cast<int>(j));
      }
    }
  }
  return neighbours;
}

ss::SymmetryPlane plane(const Eigen::Vector3f& normal, float distance) {
  ss::SymmetryPlane result;
  result.normal = normal.normalized();
  result.distance = distance;
  return result;
}

ss::CandidateSegment everything(const ss::Cloud& cloud, const ss::SymmetryPlane& segment_plane) {
  ss::CandidateSegment segment;
  segment.points.resize(cloud.size());
  std::iota(segment.points.begin(), segment.points.end(), 0);
  segment.plane = segment_plane;
  return segment;
}

// Links within 1.5 cm; a reflection lands on the point nearest its mirror image within half a
// centimetre; every segment scores occlusion 1, smoothness 0.
test_support::FakeEvidence evidenceOf(const ss::Cloud& cloud) {
  test_support::FakeEvidence evidence(cloud, linksWithin(cloud, 0.015f));
  evidence.landOnNearestWithin(0.005f);
  return evidence;
}

std::vector<int> pointsOfColor(const ss::Cloud& cloud, const Rgb& color) {
  std::vector<int> points;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud[i].r == color[0] && cloud[i].g == color[1] && cloud[i].b == color[2]) points.push_back(static_cast<int>(i));
  }
  return points;
}

// A 10 x 8 cm box 6 cm tall with a box of the same footprint on it: one taller box to the shape.
std::vector<Box> boxOnBox(const Rgb& upper_color) {
  return {Box{{-0.05f, -0.04f, 0.0f}, {0.05f, 0.04f, 0.06f}, kRed},
          Box{{-0.05f, -0.04f, 0.06f}, {0.05f, 0.04f, 0.12f}, upper_color}};
}

const ss::SymmetryPlane kAcross = plane(Eigen::Vector3f::UnitX(), 0.0f);

std::size_t split(std::vector<ss::CandidateSegment>& segments, const ss::Cloud& cloud,
                  const std::vector<ss::CandidateSegment>& found = {}, const ss::ColorSeamParams& params = {}) {
  return ss::splitAtColorSeams(segments, found, evidenceOf(cloud), params);
}

ss::ColorSeamParams withFlushSeams() {
  ss::ColorSeamParams params;
  params.split_flush_seams = true;
  return params;
}

}  // namespace

TEST(ColorSeams, AFlatSeamSplitsOnlyBetweenPartsThatStandAlone) {
  // To the geometry a box on a box of its footprint is one taller box, as is a box printed in
  // two colours. Each box of the stack is mirrored onto itself by the plane they share; each
  // half of a box printed in two colours either side of its plane is mirrored onto the other.
  const ss::Cloud stack = boxSurfaces(boxOnBox(kBlue));
  std::vector<ss::CandidateSegment> segments = {everything(stack, kAcross)};
  EXPECT_EQ(split(segments, stack), 1u);
  ss::Cloud printed = boxSurfaces({Box{{-0.05f, -0.04f, 0.0f}, {0.05f, 0.04f, 0.12f}, kRed}});
  for (auto& point : printed) {
    if (point.x < 0.0f) point.r = kBlue[0], point.g = kBlue[1], point.b = kBlue[2];
  }
  ASSERT_GT(pointsOfColor(printed, kBlue).size(), 0.3 * printed.size());
  segments = {everything(printed, kAcross)};
  EXPECT_EQ(split(segments, printed), 0u);
  EXPECT_EQ(segments.size(), 1u);
  // Without split_flush_seams only concave creases part colours.
  ss::ColorSeamParams creases_only;
  creases_only.split_flush_seams = false;
  segments = {everything(stack, kAcross)};
  EXPECT_EQ(split(segments, stack, {}, creases_only), 0u);
}

TEST(ColorSeams, ABoxOnABoxOfTheSameFootprintIsTwoObjectsWithFlushSeams) {
  const ss::Cloud cloud = boxSurfaces(boxOnBox(kBlue));
  std::vector<ss::CandidateSegment> segments = {everything(cloud, kAcross)};
  EXPECT_EQ(split(segments, cloud, {}, withFlushSeams()), 1u);
  ASSERT_EQ(segments.size(), 2u);
  EXPECT_EQ(segments[0].points, pointsOfColor(cloud, kRed));
  EXPECT_EQ(segments[1].points, pointsOfColor(cloud, kBlue));
  for (const auto& segment : segments) {
    EXPECT_LT(ss::planeAngleDeg(segment.plane, kAcross), 1e-3f) << "the shared plane fits each box";
    EXPECT_FLOAT_EQ(segment.scores.occlusion, 1.0f) << "each part is scored";
  }
}

TEST(ColorSeams, ABoxOnABoxOfOneColourStaysOneTallBox) {
  const ss::Cloud cloud = boxSurfaces(boxOnBox(kRed));
  std::vector<ss::CandidateSegment> segments = {everything(cloud, kAcross)};
  EXPECT_EQ(split(segments, cloud), 0u);
  EXPECT_EQ(segments.size(), 1u);
}

TEST(ColorSeams, EachPartTakesThePlaneItContradictsLeast) {
  // The stack's horizontal mid-plane mirrors the lower box onto the upper one: no plane of
  // either alone. A segment found on the stack brings the vertical plane both share.
  const ss::Cloud cloud = boxSurfaces(boxOnBox(kBlue));
  const ss::SymmetryPlane between = plane(Eigen::Vector3f::UnitZ(), -0.06f);
  std::vector<ss::CandidateSegment> segments = {everything(cloud, between)};
  const std::vector<ss::CandidateSegment> found = {everything(cloud, kAcross)};
  EXPECT_EQ(split(segments, cloud, found, withFlushSeams()), 1u);
  ASSERT_EQ(segments.size(), 2u);
  for (const auto& segment : segments) EXPECT_LT(ss::planeAngleDeg(segment.plane, kAcross), 1e-3f);
}

TEST(ColorSeams, BoxesOfOneDepthPushedIntoARowAreSeparateObjects) {
  // A short box against a tall one: their front and back faces run on flush; the short box's
  // top meets the tall box's side at a concave crease, as separate objects do.
  const ss::Cloud cloud = boxSurfaces({Box{{-0.08f, -0.04f, 0.0f}, {0.0f, 0.04f, 0.07f}, kRed},
                                       Box{{0.0f, -0.04f, 0.0f}, {0.08f, 0.04f, 0.12f}, kBlue}});
  std::vector<ss::CandidateSegment> segments = {everything(cloud, plane(Eigen::Vector3f::UnitY(), 0.0f))};
  EXPECT_EQ(split(segments, cloud), 1u);
  ASSERT_EQ(segments.size(), 2u);
  EXPECT_EQ(segments[0].points, pointsOfColor(cloud, kRed));
  EXPECT_EQ(segments[1].points, pointsOfColor(cloud, kBlue));
}

TEST(ColorSeams, FlushBoxesOfOneHeightInARowAreSeparateObjects) {
  // Three boxes of one depth and height pushed into a row: no crease between them, and the
  // row's plane (the middle box's) mirrors each end box onto the other. Each end box mirrors
  // onto itself about its own middle, halfway between its seam and its far face.
  const Rgb yellow{{210, 170, 30}};
  const ss::Cloud cloud = boxSurfaces({Box{{-0.11f, -0.04f, 0.0f}, {-0.05f, 0.04f, 0.1f}, kRed},
                                       Box{{-0.05f, -0.04f, 0.0f}, {0.05f, 0.04f, 0.1f}, kBlue},
                                       Box{{0.05f, -0.04f, 0.0f}, {0.11f, 0.04f, 0.1f}, yellow}});
  std::vector<ss::CandidateSegment> segments = {everything(cloud, kAcross)};
  EXPECT_EQ(split(segments, cloud), 1u);
  ASSERT_EQ(segments.size(), 3u);
  std::vector<std::vector<int>> parts;
  for (const auto& segment : segments) parts.push_back(segment.points);
  std::sort(parts.begin(), parts.end());
  std::vector<std::vector<int>> expected = {pointsOfColor(cloud, kRed), pointsOfColor(cloud, kBlue),
                                            pointsOfColor(cloud, yellow)};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(parts, expected);
}

TEST(ColorSeams, ALidColouredApartAtTheRimStaysWithItsBox) {
  // The colour edge follows the box's convex top edge: one object made of two parts.
  ss::Cloud cloud = boxSurfaces({Box{{-0.05f, -0.04f, 0.0f}, {0.05f, 0.04f, 0.12f}, kRed}});
  for (auto& point : cloud) {
    if (point.normal_z > 0.5f) {
      point.r = kBlue[0];
      point.g = kBlue[1];
      point.b = kBlue[2];
    }
  }
  ASSERT_GT(pointsOfColor(cloud, kBlue).size(), 0.1 * cloud.size());
  std::vector<ss::CandidateSegment> segments = {everything(cloud, kAcross)};
  EXPECT_EQ(split(segments, cloud), 0u);
  EXPECT_EQ(segments.size(), 1u);
}

TEST(ColorSeams, ACapOnANarrowNeckStaysWithItsBottle) {
  // The cap meets the neck flush, but its seam is a ring far narrower than the bottle.
  ss::Cloud cloud = boxSurfaces({Box{{-0.06f, -0.06f, 0.0f}, {0.06f, 0.06f, 0.08f}, kRed},
                                 Box{{-0.015f, -0.015f, 0.08f}, {0.015f, 0.015f, 0.12f}, kRed},
                                 Box{{-0.015f, -0.015f, 0.12f}, {0.015f, 0.015f, 0.16f}, kBlue}});
  const std::vector<int> cap = pointsOfColor(cloud, kBlue);
  ASSERT_GT(cap.size(), 40u);
  ss::ColorSeamParams params = withFlushSeams();
  params.min_part_fraction = 0.05f;  // the cap is a candidate part; only its seam's span decides
  params.min_part_points = 20;
  ASSERT_GT(cap.size(), params.min_part_fraction * cloud.size());
  std::vector<ss::CandidateSegment> segments = {everything(cloud, kAcross)};
  EXPECT_EQ(ss::splitAtColorSeams(segments, {}, evidenceOf(cloud), params),
            0u);
  // The same cap on a neck as wide as the bottle would be a box on a box.
  const ss::Cloud wide = boxSurfaces({Box{{-0.015f, -0.015f, 0.0f}, {0.015f, 0.015f, 0.12f}, kRed},
                                      Box{{-0.015f, -0.015f, 0.12f}, {0.015f, 0.015f, 0.16f}, kBlue}});
  segments = {everything(wide, kAcross)};
  EXPECT_EQ(ss::splitAtColorSeams(segments, {}, evidenceOf(wide), params),
            1u);
}

TEST(ColorSeams, APrintedObjectIsNotCutAlongItsPrint) {
  // Speckled colours: many small regions, no large ones covering the object.
  ss::Cloud cloud = boxSurfaces(boxOnBox(kRed));
  std::mt19937 random(7);
  std::uniform_int_distribution<int> channel(0, 255);
  for (auto& point : cloud) {
    point.r = static_cast<std::uint8_t>(channel(random));
    point.g = static_cast<std::uint8_t>(channel(random));
    point.b = static_cast<std::uint8_t>(channel(random));
  }
  std::vector<ss::CandidateSegment> segments = {everything(cloud, kAcross)};
  EXPECT_EQ(split(segments, cloud), 0u);
}

namespace {

// Every point of `cloud` within `box` speckled in random colours: print, no uniform region.
void printOver(ss::Cloud& cloud, const Box& box, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> channel(0, 255);
  for (auto& point : cloud) {
    if (!box.contains(point.getVector3fMap())) continue;
    point.r = static_cast<std::uint8_t>(channel(random));
    point.g = static_cast<std::uint8_t>(channel(random));
    point.b = static_cast<std::uint8_t>(channel(random));
  }
}

}  // namespace

TEST(ColorSeams, APrintedBoxAgainstAPlainOneIsItsOwnObject) {
  // The short plain box's top meets the tall printed box's side at a concave crease. The
  // print is a hundred small regions, no large one; taken together it is a part of its own.
  const Box plain{{-0.08f, -0.04f, 0.0f}, {0.0f, 0.04f, 0.07f}, kRed};
  const Box printed{{0.0f, -0.04f, 0.0f}, {0.08f, 0.04f, 0.12f}, kBlue};
  ss::Cloud cloud = boxSurfaces({plain, printed});
  const std::vector<int> red = pointsOfColor(cloud, kRed);
  printOver(cloud, Box{{0.0005f, -1.0f, -1.0f}, {1.0f, 1.0f, 1.0f}, kBlue}, 11);
  ASSERT_LT(red.size(), ss::ColorSeamParams{}.min_coverage * cloud.size());
  std::vector<ss::CandidateSegment> segments = {everything(cloud, plane(Eigen::Vector3f::UnitY(), 0.0f))};
  EXPECT_EQ(split(segments, cloud), 1u);
  ASSERT_EQ(segments.size(), 2u);
  EXPECT_EQ(segments[0].points, red);
  std::vector<int> rest;
  for (int i = 0; i < static_cast<int>(cloud.size()); ++i) {
    if (!std::binary_search(red.begin(), red.end(), i)) rest.push_back(i);
  }
  EXPECT_EQ(segments[1].points, rest);
}

TEST(ColorSeams, APlainFaceOfItsOwnPrintsColourStaysWithThePrint) {
  // The same two parts at the same concave crease, but a third of the print is blobs of the
  // plain part's red: one print's palette over both (a printed U whose inner face is plain), one
  // object. The blobs (3 cm, 2 cm apart, away from the crease) stay print, no region of their own.
  const Box plain{{-0.08f, -0.04f, 0.0f}, {0.0f, 0.04f, 0.07f}, kRed};
  const Box printed{{0.0f, -0.04f, 0.0f}, {0.08f, 0.04f, 0.12f}, kBlue};
  ss::Cloud cloud = boxSurfaces({plain, printed});
  printOver(cloud, Box{{0.0005f, -1.0f, -1.0f}, {1.0f, 1.0f, 1.0f}, kBlue}, 11);
  std::vector<int> plain_part, print_part;
  for (int i = 0; i < static_cast<int>(cloud.size()); ++i) {
    auto& point = cloud[i];
    (point.x <= 0.0005f ? plain_part : print_part).push_back(i);
    if (point.x <= 0.02f) continue;
    // In-face cell coordinates: the two axes the face spans.
    const Eigen::Vector3f p = point.getVector3fMap() * 100.0f;
    const Eigen::Vector3f n = point.getNormalVector3fMap().cwiseAbs();
    int across = 0;
    n.maxCoeff(&across);
    bool in_blob = true;
    for (int axis = 0; axis < 3; ++axis) {
      if (axis != across) in_blob = in_blob && static_cast<int>(std::floor(p[axis] + 100.0f)) % 5 < 3;
    }
    if (!in_blob) continue;
    point.r = kRed[0];
    point.g = kRed[1];
    point.b = kRed[2];
  }
  ASSERT_GT(ss::colorOverlap(cloud, plain_part, print_part), 0.3f);
  const ss::SymmetryPlane across = plane(Eigen::Vector3f::UnitY(), 0.0f);
  ss::ColorSeamParams params;
  params.min_color_overlap = 0.3f;
  std::vector<ss::CandidateSegment> segments = {everything(cloud, across)};
  EXPECT_EQ(split(segments, cloud, {}, params), 0u);
  EXPECT_EQ(segments.size(), 1u);
  params.min_color_overlap = 0.0f;  // off: the crease parts them
  segments = {everything(cloud, across)};
  EXPECT_EQ(split(segments, cloud, {}, params), 1u);
}

TEST(ColorSeams, PrintMeetingAPlainPanelFlushStaysOneObject) {
  // A box on a box of its footprint, the lower plain, the upper printed: to the geometry one
  // tall box, and a plain panel running flush into print is how packaging is printed.
  ss::Cloud cloud = boxSurfaces(boxOnBox(kBlue));
  printOver(cloud, Box{{-1.0f, -1.0f, 0.0605f}, {1.0f, 1.0f, 1.0f}, kBlue}, 13);
  ASSERT_GT(pointsOfColor(cloud, kRed).size(), 0.3 * cloud.size());
  std::vector<ss::CandidateSegment> segments = {everything(cloud, kAcross)};
  EXPECT_EQ(ss::splitAtColorSeams(segments, {}, evidenceOf(cloud), withFlushSeams()), 0u);
  EXPECT_EQ(segments.size(), 1u);  // both plain, the same stack is two boxes (the test above)
}

TEST(ColorSeams, OneObjectSeenInSeparatePiecesStaysWhole) {
  // A box's left and right ends with its middle hidden: two large regions of one colour that
  // never meet, so no seam says they are two objects.
  const ss::Cloud cloud = boxSurfaces({Box{{-0.12f, -0.03f, 0.0f}, {-0.04f, 0.03f, 0.1f}, kRed},
                                       Box{{0.04f, -0.03f, 0.0f}, {0.12f, 0.03f, 0.1f}, kRed}});
  std::vector<ss::CandidateSegment> segments = {everything(cloud, kAcross)};
  EXPECT_EQ(split(segments, cloud), 0u);
  EXPECT_EQ(segments.size(), 1u);
}

TEST(ColorSeams, AnObjectStandingOnAWiderOneIsItsOwnObject) {
  // A smaller box centred on a wider one: their seam is the concave crease round its foot,
  // which no cut could cut when one plane mirrors both onto themselves.
  const ss::Cloud cloud = boxSurfaces({Box{{-0.06f, -0.05f, 0.0f}, {0.06f, 0.05f, 0.06f}, kRed},
                                       Box{{-0.03f, -0.03f, 0.06f}, {0.03f, 0.03f, 0.12f}, kBlue}});
  std::vector<ss::CandidateSegment> segments = {everything(cloud, kAcross)};
  EXPECT_EQ(split(segments, cloud), 1u);
  ASSERT_EQ(segments.size(), 2u);
  EXPECT_EQ(segments[0].points, pointsOfColor(cloud, kRed));
  EXPECT_EQ(segments[1].points, pointsOfColor(cloud, kBlue));
}

TEST(ColorSeams, ASmallPartColouredApartAtAConcaveCreaseStaysWithItsObject) {
  // A handle-sized block on a box's side: a concave seam, but too small a part to be an object.
  const ss::Cloud cloud = boxSurfaces({Box{{-0.06f, -0.05f, 0.0f}, {0.06f, 0.05f, 0.12f}, kRed},
                                       Box{{0.06f, -0.02f, 0.03f}, {0.09f, 0.02f, 0.09f}, kBlue}});
  ss::ColorSeamParams params;
  params.min_part_points = 20;
  params.min_part_fraction = 0.08f;
  const std::size_t handle = pointsOfColor(cloud, kBlue).size();
  ASSERT_GE(handle, params.min_part_fraction * cloud.size()) << "a candidate part, kept by its size alone";
  ASSERT_LT(handle, params.min_touching_part_fraction * cloud.size());
  std::vector<ss::CandidateSegment> segments = {everything(cloud, kAcross)};
  EXPECT_EQ(ss::splitAtColorSeams(segments, {}, evidenceOf(cloud), params),
            0u);
}

TEST(ColorSeams, ASmallBoxBesideALargeOneIsItsOwnObject) {
  // A small box against a large one's side, one plane across their depth mirroring each onto
  // itself: far below min_touching_part_fraction, but an object of its own, not a handle.
  const ss::Cloud cloud = boxSurfaces({Box{{-0.12f, -0.04f, 0.0f}, {0.0f, 0.04f, 0.14f}, kRed},
                                       Box{{0.0f, -0.03f, 0.0f}, {0.04f, 0.03f, 0.05f}, kBlue}});
  const ss::ColorSeamParams params;
  const std::size_t small = pointsOfColor(cloud, kBlue).size();
  ASSERT_LT(small, params.min_touching_part_fraction * cloud.size());
  std::vector<ss::CandidateSegment> segments = {everything(cloud, plane(Eigen::Vector3f::UnitY(), 0.0f))};
  EXPECT_EQ(split(segments, cloud, {}, params), 1u);
  ASSERT_EQ(segments.size(), 2u);
  EXPECT_EQ(segments[0].points, pointsOfColor(cloud, kRed));
  EXPECT_EQ(segments[1].points, pointsOfColor(cloud, kBlue));
  // The same small part as a flat panel on that side (one face, 1 cm thick) is no object.
  const ss::Cloud panel = boxSurfaces({Box{{-0.12f, -0.04f, 0.0f}, {0.0f, 0.04f, 0.14f}, kRed},
                                       Box{{0.0f, -0.03f, 0.02f}, {0.01f, 0.03f, 0.1f}, kBlue}});
  std::vector<ss::CandidateSegment> with_panel = {everything(panel, plane(Eigen::Vector3f::UnitY(), 0.0f))};
  ss::ColorSeamParams small_parts = params;
  small_parts.min_part_fraction = 0.05f;
  ASSERT_GE(pointsOfColor(panel, kBlue).size(), small_parts.min_part_fraction * panel.size());
  EXPECT_EQ(split(with_panel, panel, {}, small_parts), 0u);
}

namespace {

// A red box against a blue one, the red box's segment with the blue box's top face too (the
// strip a cut takes along the crease); the blue segment has the rest of the blue box.
struct StrayStrip {
  ss::Cloud cloud = boxSurfaces({Box{{-0.08f, -0.04f, 0.0f}, {0.0f, 0.04f, 0.12f}, kRed},
                                 Box{{0.0f, -0.04f, 0.0f}, {0.08f, 0.04f, 0.07f}, kBlue}});
  std::vector<ss::CandidateSegment> segments = std::vector<ss::CandidateSegment>(2);
  std::vector<int> strip;
  StrayStrip() {
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const bool blue_top = cloud[i].b == kBlue[2] && cloud[i].normal_z > 0.5f;
      if (blue_top) strip.push_back(static_cast<int>(i));
      segments[(cloud[i].r == kRed[0] || blue_top) ? 0 : 1].points.push_back(static_cast<int>(i));
    }
  }
};

}  // namespace

TEST(ColorSeams, AStripOfTheNextObjectsColourMovesToThatObject) {
  StrayStrip scene;
  ASSERT_LT(scene.strip.size(), 0.3 * scene.segments[0].points.size());
  EXPECT_EQ(ss::moveStrayColorPieces(scene.segments, scene.cloud, linksWithin(scene.cloud, 0.015f), {}), scene.strip.size());
  EXPECT_EQ(scene.segments[0].points, pointsOfColor(scene.cloud, kRed));
  EXPECT_EQ(scene.segments[1].points, pointsOfColor(scene.cloud, kBlue));
}

TEST(ColorSeams, APieceLikeNoNeighbourStays) {
  // The strip recoloured green: print on the red box, not a piece of the blue one.
  StrayStrip scene;
  for (int i : scene.strip) scene.cloud[i].g = 200, scene.cloud[i].r = scene.cloud[i].b = 40;
  const auto before = scene.segments;
  EXPECT_EQ(ss::moveStrayColorPieces(scene.segments, scene.cloud, linksWithin(scene.cloud, 0.015f), {}), 0u);
  EXPECT_EQ(scene.segments[0].points, before[0].points);
  EXPECT_EQ(scene.segments[1].points, before[1].points);
}

namespace {

// A 12 x 8 x 10 cm box coloured red left of `boundary(z)` and blue right of it, on every face.
ss::Cloud twoColourBox(float (*boundary)(float z)) {
  ss::Cloud cloud = boxSurfaces({Box{{-0.06f, -0.04f, 0.0f}, {0.06f, 0.04f, 0.1f}, kRed}});
  for (ss::PointT& p : cloud) {
    if (p.x < boundary(p.z)) continue;
    p.r = kBlue[0];
    p.g = kBlue[1];
    p.b = kBlue[2];
  }
  return cloud;
}

}  // namespace

TEST(ColorSeams, ASeamThatStepsAcrossTheFacesIsPrintNotWhereObjectsMeet) {
  // Two objects meet flush on one plane, their contact: red and blue halves split at x = 0 are
  // two boxes of one depth pushed together. Where the colour edge steps 3 cm halfway up, it is
  // print on one box: no contact plane runs through it. Both halves mirror onto themselves
  // about the front-to-back plane either way.
  const ss::SymmetryPlane front_to_back = plane(Eigen::Vector3f::UnitY(), 0.0f);
  const ss::Cloud flush = twoColourBox([](float) { return 0.0f; });
  std::vector<ss::CandidateSegment> segments = {everything(flush, front_to_back)};
  EXPECT_EQ(split(segments, flush, {}, withFlushSeams()), 1u);
  EXPECT_EQ(segments.size(), 2u);

  const ss::Cloud stepped = twoColourBox([](float z) { return z < 0.05f ? 0.0f : 0.03f; });
  segments = {everything(stepped, front_to_back)};
  EXPECT_EQ(split(segments, stepped, {}, withFlushSeams()), 0u);
  EXPECT_EQ(segments.size(), 1u);
  // Without the contact-plane test the print's edge parts the box.
  ss::ColorSeamParams any_seam = withFlushSeams();
  any_seam.max_flush_seam_offset = 0.0f;
  segments = {everything(stepped, front_to_back)};
  EXPECT_EQ(split(segments, stepped, {}, any_seam), 1u);
}
