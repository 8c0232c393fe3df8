// Stage footprints: an island no cut reached gets the vertical planes along its footprint's axes,
// through the middle of its extent; groups of several objects and covered islands get none.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "symmetry_segmentation/symmetry/footprint_hypotheses.h"
#include "test_clouds.h"

namespace ss = symmetry_segmentation;

namespace {

std::vector<int> all(const ss::Cloud& cloud) {
  std::vector<int> indices(cloud.size());
  std::iota(indices.begin(), indices.end(), 0);
  return indices;
}

}  // namespace

TEST(FootprintHypotheses, AnLShapeGetsItsSymmetryPlaneThroughTheMiddleOfItsWidth) {
  // A slab 20 x 8 cm with an upright at one end; its front face (y = -4 cm) seen three times as
  // densely as the rest, so the points' mean lies off the middle.
  ss::Cloud cloud;
  test_clouds::addBox(cloud, {-0.1f, -0.04f, 0.0f}, {0.2f, 0.08f, 0.03f}, 0.005f);
  test_clouds::addBox(cloud, {-0.1f, -0.04f, 0.03f}, {0.03f, 0.08f, 0.12f}, 0.005f);
  const std::size_t base = cloud.size();
  for (std::size_t i = 0; i < base; ++i) {
    if (cloud[i].y < -0.039f) {
      cloud.push_back(cloud[i]);
      cloud.push_back(cloud[i]);
    }
  }
  const auto hypotheses = ss::footprintHypotheses(cloud, all(cloud), Eigen::Vector3f::UnitZ(), 0.3f);
  ASSERT_EQ(hypotheses.size(), 2u);
  // The longer axis first: the plane across the length (no symmetry of an L, but a guess).
  EXPECT_GT(std::fabs(hypotheses[0].plane.normal.x()), 0.99f);
  EXPECT_NEAR(hypotheses[0].plane.distance, 0.0f, 0.003f);
  // Then the plane across the width, through its middle: the L's own.
  EXPECT_GT(std::fabs(hypotheses[1].plane.normal.y()), 0.99f);
  EXPECT_NEAR(hypotheses[1].plane.distance, 0.0f, 0.003f);
  for (const auto& hypothesis : hypotheses) {
    EXPECT_LT(std::fabs(hypothesis.plane.normal.z()), 1e-4f) << "vertical planes";
    EXPECT_EQ(hypothesis.anchor, all(cloud)) << "the cut keeps this island";
  }
}

TEST(FootprintHypotheses, GroupsLongerThanAnObjectGetNone) {
  ss::Cloud cloud;
  test_clouds::addBox(cloud, {-0.25f, -0.04f, 0.0f}, {0.5f, 0.08f, 0.1f}, 0.01f);
  EXPECT_TRUE(ss::footprintHypotheses(cloud, all(cloud), Eigen::Vector3f::UnitZ(), 0.3f).empty());
  EXPECT_EQ(ss::footprintHypotheses(cloud, all(cloud), Eigen::Vector3f::UnitZ(), 0.6f).size(), 2u);
  EXPECT_TRUE(ss::footprintHypotheses(cloud, {0, 1}, Eigen::Vector3f::UnitZ(), 0.3f).empty());
}

TEST(FootprintHypotheses, OnlyIslandsNoSegmentCovered) {
  const std::vector<std::vector<int>> islands = {{0, 1, 2, 3}, {10, 11, 12, 13}, {20, 21, 22, 23}};
  ss::CandidateSegment over_first, part_of_second;
  over_first.points = {0, 1, 2, 3, 4, 5};
  part_of_second.points = {10};
  // The second island is covered a quarter: enough at 0.25, not at 0.3.
  const auto left = ss::groupsNoSegmentCovers(islands, {over_first, part_of_second}, 0.25f);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0], islands[2]);
  const auto stricter = ss::groupsNoSegmentCovers(islands, {over_first, part_of_second}, 0.3f);
  ASSERT_EQ(stricter.size(), 2u);
  EXPECT_EQ(stricter[0], islands[1]);
  EXPECT_EQ(stricter[1], islands[2]);
}
