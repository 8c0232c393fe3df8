// The table's surface follows a table that bends away from its plane, and a board lying on it
// stays above it; the plane through the table comes out the same whichever plane it began from.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "symmetry_segmentation/table_grid.h"
#include "symmetry_segmentation/table_surface.h"

namespace ss = symmetry_segmentation;

namespace {

// A 1 m x 0.8 m table at z = 0 bending up by `bend` * x^2 (x, y in m), 4 mm apart, with 1 mm of
// noise, normals up; with `board`, a 20 cm x 30 cm board 15 mm thick lies on it at (0.2, 0.1).
struct Table {
  ss::Cloud cloud;
  std::vector<int> indices;
  float bend;

  float tableHeight(float x) const { return bend * x * x; }

  Table(float bend_, bool board) : bend(bend_) {
    std::mt19937 random(7);
    std::normal_distribution<float> noise(0.0f, 0.001f);
    for (float x = -0.5f; x < 0.5f; x += 0.004f) {
      for (float y = -0.4f; y < 0.4f; y += 0.004f) {
        const bool on_board = board && std::fabs(x - 0.2f) < 0.1f && std::fabs(y - 0.1f) < 0.15f;
        ss::PointT p;
        p.x = x;
        p.y = y;
        p.z = tableHeight(x) + (on_board ? 0.015f : 0.0f) + noise(random);
        p.normal_x = p.normal_y = 0.0f;
        p.normal_z = 1.0f;
        indices.push_back(static_cast<int>(cloud.size()));
        cloud.push_back(p);
      }
    }
  }
};

}  // namespace

TEST(TableSurface, FollowsATableThatBendsAwayFromItsPlane) {
  // 8 mm up at either end: a cut 5 mm over the plane takes the far ends' table as object.
  const Table table(0.032f, false);
  const auto surface = ss::TableSurface::fit(table.cloud, table.indices, ss::PlaneCoefficients(0, 0, 1, 0), 0.01f,
                                            true, 0.03f);
  ASSERT_TRUE(surface);
  for (float x : {-0.45f, -0.2f, 0.0f, 0.3f, 0.45f}) {
    const Eigen::Vector3f p(x, 0.1f, table.tableHeight(x));
    EXPECT_NEAR(surface->height(p), 0.0f, 0.0015f) << "at x = " << x;
  }
}

TEST(TableGrid, HeightsAreOverTheFittedTopCellsOnThePlane) {
  // What lies over or under a footprint (hanging and rising segments, table sightings) is
  // measured like everything else: from the bending top, not from its plane.
  const Table table(0.032f, false);
  const ss::PlaneCoefficients plane(0, 0, 2, 0);  // any length of normal
  const auto surface = ss::TableSurface::fit(table.cloud, table.indices, plane, 0.01f, true, 0.03f);
  ASSERT_TRUE(surface);
  const ss::TableGrid over_plane(plane, 0.05f);
  const ss::TableGrid over_top(ss::TableTop(plane, surface), 0.05f);
  const Eigen::Vector3f far_end(0.45f, 0.1f, table.tableHeight(0.45f) + 0.03f);  // 3 cm over the top there
  EXPECT_NEAR(over_plane.height(far_end), 0.03f + table.tableHeight(0.45f), 1e-5f);
  EXPECT_NEAR(over_top.height(far_end), 0.03f, 0.0015f);
  EXPECT_EQ(over_top.cellOf(far_end), over_plane.cellOf(far_end));
  EXPECT_EQ(over_top.cellOf(far_end), over_top.cellOf(Eigen::Vector3f(0.45f, 0.1f, -1.0f)));  // seen from above
  EXPECT_NEAR(over_top.up().z(), 1.0f, 1e-6f);
}

TEST(TableSurface, ABoardLyingOnTheTableStaysAboveIt) {
  const Table table(0.0f, true);
  const auto surface = ss::TableSurface::fit(table.cloud, table.indices, ss::PlaneCoefficients(0, 0, 1, 0), 0.02f,
                                            true, 0.03f);
  ASSERT_TRUE(surface);
  EXPECT_NEAR(surface->height(Eigen::Vector3f(0.2f, 0.1f, 0.015f)), 0.015f, 0.0015f);  // the board's middle
  EXPECT_NEAR(surface->height(Eigen::Vector3f(-0.3f, -0.2f, 0.0f)), 0.0f, 0.0015f);
  EXPECT_LT(surface->maxLift(), 0.003f);
}

TEST(TableSurface, ThePlaneThroughTheTableDoesNotDependOnThePlaneItBeganFrom) {
  const Table table(0.0f, false);
  // 5 mm too high and tilted by half a degree about y.
  const float tilt = 0.5f * static_cast<float>(M_PI) / 180.0f;
  const ss::PlaneCoefficients start(std::sin(tilt), 0.0f, std::cos(tilt), -0.005f);
  const auto surface = ss::TableSurface::fit(table.cloud, table.indices, start, 0.01f, true, 0.03f);
  ASSERT_TRUE(surface);
  const ss::PlaneCoefficients plane = surface->plane();
  EXPECT_GT(plane.head<3>().dot(Eigen::Vector3f::UnitZ()), std::cos(0.05f * static_cast<float>(M_PI) / 180.0f));
  EXPECT_NEAR(plane[3], 0.0f, 0.0005f);
  for (float x : {-0.45f, 0.0f, 0.45f}) EXPECT_NEAR(surface->height(Eigen::Vector3f(x, 0.0f, 0.0f)), 0.0f, 0.001f);
}

TEST(TableSurface, TooLittleTableTellsNoSurface) {
  Table table(0.0f, false);
  table.indices.resize(40);  // one row's first 16 cm: a handful of cells
  EXPECT_FALSE(ss::TableSurface::fit(table.cloud, table.indices, ss::PlaneCoefficients(0, 0, 1, 0), 0.01f, true, 0.03f));
  EXPECT_FALSE(ss::TableSurface::fit(table.cloud, {}, ss::PlaneCoefficients(0, 0, 1, 0), 0.01f, true, 0.03f));
  EXPECT_FALSE(ss::TableSurface::fit(table.cloud, table.indices, ss::PlaneCoefficients(0, 0, 0, 0), 0.01f, true, 0.03f));
}

TEST(TableSurface, AStripOfCellsAlongALineTellsNoPlane) {
  // The table's points 4 cm wide across its 1 m: enough cells, but a plane through them could
  // tilt about the strip at will.
  Table table(0.0f, false);
  std::vector<int> strip;
  for (int i : table.indices) {
    if (std::fabs(table.cloud[i].y) < 0.02f) strip.push_back(i);
  }
  EXPECT_FALSE(ss::TableSurface::fit(table.cloud, strip, ss::PlaneCoefficients(0, 0, 1, 0), 0.01f, true, 0.02f));
  std::vector<int> wider;
  for (int i : table.indices) {
    if (std::fabs(table.cloud[i].y) < 0.1f) wider.push_back(i);
  }
  EXPECT_TRUE(ss::TableSurface::fit(table.cloud, wider, ss::PlaneCoefficients(0, 0, 1, 0), 0.01f, true, 0.02f));
}
