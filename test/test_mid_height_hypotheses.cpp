// Part of stage upright: horizontal planes halfway up objects standing on the table or on
// another object.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "symmetry_segmentation/symmetry/mid_height_hypotheses.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"
#include "test_clouds.h"

namespace ss = symmetry_segmentation;

namespace {

const ss::PlaneCoefficients kTable(0.0f, 0.0f, 1.0f, 0.0f);  // z = 0, normal up
constexpr float kVoxel = 0.01f;

/// A horizontal face at height z over [x0, x1] x [y0, y1], 1 cm apart, labelled `label`; points
/// of (x, y) inside `hole` (a foot standing on the face) are not seen.
void addFace(ss::Cloud& cloud, std::vector<int>& labels, float x0, float x1, float y0, float y1, float z, int label,
             const Eigen::AlignedBox2f& hole = Eigen::AlignedBox2f()) {
  for (float x = x0; x <= x1 + 1e-4f; x += kVoxel) {
    for (float y = y0; y <= y1 + 1e-4f; y += kVoxel) {
      if (!hole.isEmpty() && hole.contains(Eigen::Vector2f(x, y))) continue;
      ss::PointT p;
      p.x = x; p.y = y; p.z = z;
      p.normal_x = 0.0f; p.normal_y = 0.0f; p.normal_z = 1.0f;
      cloud.push_back(p);
      labels.push_back(label);
    }
  }
}

/// The heights of the horizontal planes proposed, sorted.
std::vector<float> planeHeights(const std::vector<ss::SymmetryHypothesis>& hypotheses) {
  std::vector<float> heights;
  for (const ss::SymmetryHypothesis& h : hypotheses) {
    EXPECT_LT(ss::planeAngleDeg(h.plane, ss::SymmetryPlane{Eigen::Vector3f::UnitZ(), 0.0f}), 0.01f);
    heights.push_back(-h.plane.distance / h.plane.normal.z());
  }
  std::sort(heights.begin(), heights.end());
  return heights;
}

}  // namespace

TEST(MidHeightHypotheses, ABoxOnTheTableProposesThePlaneHalfwayUpItAnchoredOnItsTop) {
  ss::Cloud cloud;
  std::vector<int> labels;
  addFace(cloud, labels, 0.0f, 0.1f, 0.0f, 0.08f, 0.12f, 1);
  const auto hypotheses = ss::midHeightHypotheses(cloud, ss::surfaceShapes(cloud, labels), kTable, ss::UprightHypothesisParams{}, kVoxel);
  ASSERT_EQ(hypotheses.size(), 1u);
  EXPECT_NEAR(planeHeights(hypotheses)[0], 0.06f, 1e-4f);
  EXPECT_EQ(hypotheses[0].anchor.size(), cloud.size());
  EXPECT_EQ(hypotheses[0].support, static_cast<int>(cloud.size()));
}

TEST(MidHeightHypotheses, ACanOnAWideBoxProposesThePlanesHalfwayUpEach) {
  // The box's top 10 cm high is seen around the can's foot; the can's top is 18 cm higher.
  ss::Cloud cloud;
  std::vector<int> labels;
  const Eigen::AlignedBox2f foot(Eigen::Vector2f(0.04f, 0.04f), Eigen::Vector2f(0.12f, 0.12f));
  addFace(cloud, labels, 0.0f, 0.16f, 0.0f, 0.16f, 0.10f, 1, foot);
  addFace(cloud, labels, 0.05f, 0.11f, 0.05f, 0.11f, 0.28f, 2);
  // A box as high as the wide one, 30 cm away: no stack with the can.
  addFace(cloud, labels, 0.5f, 0.6f, 0.0f, 0.1f, 0.10f, 3);
  const auto heights =
      planeHeights(ss::midHeightHypotheses(cloud, ss::surfaceShapes(cloud, labels), kTable, ss::UprightHypothesisParams{}, kVoxel));
  ASSERT_EQ(heights.size(), 4u);
  EXPECT_NEAR(heights[0], 0.05f, 1e-4f);  // the wide box
  EXPECT_NEAR(heights[1], 0.05f, 1e-4f);  // the far box
  EXPECT_NEAR(heights[2], 0.14f, 1e-4f);  // the can, were it on the table
  EXPECT_NEAR(heights[3], 0.19f, 1e-4f);  // the can on the box
}

TEST(MidHeightHypotheses, HeightsAreOverTheTablesFittedTop) {
  // The table rises by 0.1 x^2: at x = 0.4 a box top 10 cm over the table is 11.6 cm over its plane.
  const auto surface = test_clouds::bendingTableTop(0.1f);
  ASSERT_TRUE(surface);
  ss::Cloud cloud;
  std::vector<int> labels;
  addFace(cloud, labels, 0.36f, 0.44f, -0.04f, 0.04f, 0.016f + 0.1f, 1);
  const auto hypotheses =
      ss::midHeightHypotheses(cloud, ss::surfaceShapes(cloud, labels), ss::TableTop(surface->plane(), surface), ss::UprightHypothesisParams{}, kVoxel);
  ASSERT_EQ(hypotheses.size(), 1u);
  // Halfway between the table under the box (1.6 cm) and its top (11.6 cm), over the plane z = 0.
  const Eigen::Vector3f on_plane(0.4f, 0.0f, 0.066f);
  EXPECT_LT(std::fabs(ss::signedDistance(hypotheses[0].plane, on_plane)), 0.002f);
}

TEST(MidHeightHypotheses, LowFacesAndCurvedSurfacesProposeNothing) {
  ss::Cloud cloud;
  std::vector<int> labels;
  addFace(cloud, labels, 0.0f, 0.1f, 0.0f, 0.1f, 0.03f, 1);  // a book, under min_mid_height
  // A tilted face (30 deg): no top.
  for (float x = 0.3f; x <= 0.4f; x += kVoxel) {
    for (float y = 0.0f; y <= 0.1f; y += kVoxel) {
      ss::PointT p;
      p.x = x; p.y = y; p.z = 0.1f + 0.577f * (x - 0.3f);
      p.normal_x = -0.5f; p.normal_y = 0.0f; p.normal_z = 0.866f;
      cloud.push_back(p);
      labels.push_back(2);
    }
  }
  ss::UprightHypothesisParams params;
  EXPECT_TRUE(ss::midHeightHypotheses(cloud, ss::surfaceShapes(cloud, labels), kTable, params, kVoxel).empty());
  params.min_mid_height = 0.02f;
  EXPECT_EQ(ss::midHeightHypotheses(cloud, ss::surfaceShapes(cloud, labels), kTable, params, kVoxel).size(), 1u);  // the book now
  params.min_mid_height = 0.0f;
  EXPECT_TRUE(ss::midHeightHypotheses(cloud, ss::surfaceShapes(cloud, labels), kTable, params, kVoxel).empty());
}
