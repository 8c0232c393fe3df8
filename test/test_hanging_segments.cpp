// restsOnNothing: a shelf over the table rests on nothing; an object on the table, one stacked
// on another and a ball whose underside is hidden from view do.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/symmetry/hanging_segments.h"
#include "test_clouds.h"

namespace ss = symmetry_segmentation;

namespace {

const ss::PlaneCoefficients kTable(0.0f, 0.0f, 1.0f, 0.0f);
constexpr float kMargin = 0.005f;
constexpr float kCell = 0.01f;

/// Appends a box standing at `min_corner` (its visible faces, 1 cm apart); returns its indices.
std::vector<int> addBox(ss::Cloud& cloud, const Eigen::Vector3f& min_corner, const Eigen::Vector3f& size) {
  const std::size_t start = cloud.size();
  test_clouds::addBox(cloud, min_corner, size, kCell);
  std::vector<int> indices(cloud.size() - start);
  std::iota(indices.begin(), indices.end(), static_cast<int>(start));
  return indices;
}

/// Appends the part of a sphere (centre `centre`, radius `radius`) above `lowest`; returns its indices.
std::vector<int> addSphereAbove(ss::Cloud& cloud, const Eigen::Vector3f& centre, float radius, float lowest) {
  std::vector<int> indices;
  for (float theta = 0.05f; theta < static_cast<float>(M_PI); theta += 0.08f) {
    for (float phi = 0.0f; phi < 2.0f * static_cast<float>(M_PI); phi += 0.08f) {
      const Eigen::Vector3f n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      const Eigen::Vector3f p = centre + radius * n;
      if (p.z() < lowest) continue;
      ss::PointT q;
      q.x = p.x(); q.y = p.y(); q.z = p.z();
      indices.push_back(static_cast<int>(cloud.size()));
      cloud.push_back(q);
    }
  }
  return indices;
}

}  // namespace

TEST(HangingSegments, AShelfRestsOnNothingObjectsOnTheTableOrOnEachOtherDo) {
  ss::Cloud cloud;
  // A shelf board 35 cm over the table: 40 x 20 cm, 2 cm thick.
  const std::vector<int> shelf = addBox(cloud, {0.3f, 0.3f, 0.33f}, {0.4f, 0.2f, 0.02f});
  EXPECT_TRUE(ss::restsOnNothing(cloud, shelf, kTable, kMargin, kCell));
  // The table's plane given with a normal of any length says the same.
  EXPECT_TRUE(ss::restsOnNothing(cloud, shelf, ss::PlaneCoefficients(2.0f * kTable), kMargin, kCell));
  // A box 20 cm tall under it is more than five cells down: nothing holds the shelf. Nor does a
  // second shelf board beside it at its own height.
  addBox(cloud, {0.4f, 0.35f, 0.0f}, {0.1f, 0.1f, 0.2f});
  addBox(cloud, {0.71f, 0.3f, 0.33f}, {0.2f, 0.2f, 0.02f});
  EXPECT_TRUE(ss::restsOnNothing(cloud, shelf, kTable, kMargin, kCell));
  // A box standing on the table.
  const std::vector<int> lower = addBox(cloud, {0.0f, 0.0f, 0.0f}, {0.1f, 0.1f, 0.1f});
  EXPECT_FALSE(ss::restsOnNothing(cloud, lower, kTable, kMargin, kCell));
  // A short box flush on it: its base (its sides' lowest points, 11 cm up) is higher than the
  // box is tall, but the lower box's sides are under its footprint.
  const std::vector<int> upper = addBox(cloud, {0.0f, 0.0f, 0.1f}, {0.1f, 0.1f, 0.04f});
  EXPECT_FALSE(ss::restsOnNothing(cloud, upper, kTable, kMargin, kCell));
  // Without the lower box in the cloud (hidden from view), nothing is seen under it...
  ss::Cloud alone;
  const std::vector<int> upper_alone = addBox(alone, {0.0f, 0.0f, 0.1f}, {0.1f, 0.1f, 0.04f});
  EXPECT_TRUE(ss::restsOnNothing(alone, upper_alone, kTable, kMargin, kCell));
  // ...and a lower box whose side lies in the cell next to its footprint's still holds it (the
  // footprint grows by a cell: a face's voxels straddle cells).
  addBox(alone, {0.112f, 0.0f, 0.0f}, {0.1f, 0.1f, 0.1f});
  EXPECT_FALSE(ss::restsOnNothing(alone, upper_alone, kTable, kMargin, kCell));
  // A ball of 6.5 cm radius on the table, seen down to 5 cm: the gap under it (4.5 cm) is
  // smaller than what is seen of it (8 cm) - its hidden underside.
  ss::Cloud ball_cloud;
  const std::vector<int> ball = addSphereAbove(ball_cloud, {0.5f, 0.0f, 0.065f}, 0.065f, 0.05f);
  EXPECT_FALSE(ss::restsOnNothing(ball_cloud, ball, kTable, kMargin, kCell));
  // The upper half of a ball 3.5 cm over the table: the gap (9.5 cm) is taller than the half
  // (6.5 cm) - it rests on nothing in view.
  ss::Cloud raised;
  const std::vector<int> cap = addSphereAbove(raised, {0.5f, 0.0f, 0.1f}, 0.065f, 0.1f);
  EXPECT_TRUE(ss::restsOnNothing(raised, cap, kTable, kMargin, kCell));
  // Points within three cells over the margin stand on the table whatever their height.
  ss::Cloud low;
  const std::vector<int> slab = addBox(low, {0.0f, 0.0f, 0.02f}, {0.2f, 0.2f, 0.005f});
  EXPECT_FALSE(ss::restsOnNothing(low, slab, kTable, kMargin, kCell));
  // Degenerate input: no points, no plane, indices out of range.
  EXPECT_FALSE(ss::restsOnNothing(cloud, {}, kTable, kMargin, kCell));
  EXPECT_FALSE(ss::restsOnNothing(cloud, shelf, ss::PlaneCoefficients(ss::PlaneCoefficients::Zero()), kMargin, kCell));
  EXPECT_FALSE(ss::restsOnNothing(cloud, {-1, static_cast<int>(cloud.size())}, kTable, kMargin, kCell));
}

namespace {

constexpr float kCameraY = -1.0f, kCameraZ = 0.2f;

/// A board 36 cm over the table (20 x 15 cm) and, 10 cm behind it, a wall; what a camera 1 m in
/// front of the board and 20 cm over the table sees of them: it looks under the board to the
/// wall (the table under the board it sees too: left out, as if the board shaded it). With
/// `occluder`, a box 34 cm tall stands between the camera and the space under the board.
/// Returns the board's indices.
std::vector<int> boardScene(ss::Cloud& cloud, bool occluder) {
  const Eigen::Vector3f camera(0.0f, kCameraY, kCameraZ);
  const Eigen::AlignedBox3f board_box(Eigen::Vector3f(-0.105f, -0.005f, 0.355f), Eigen::Vector3f(0.105f, 0.155f, 0.365f));
  const Eigen::AlignedBox3f front_box(Eigen::Vector3f(-0.15f, -0.105f, 0.0f), Eigen::Vector3f(0.15f, -0.095f, 0.34f));
  const auto add = [&](float x, float y, float z) {
    const Eigen::Vector3f p(x, y, z);
    if (test_clouds::segmentCrossesBox(camera, p, board_box) && !board_box.contains(p)) return;
    if (occluder && test_clouds::segmentCrossesBox(camera, p, front_box) && !front_box.contains(p)) return;
    ss::PointT q;
    q.x = x; q.y = y; q.z = z;
    cloud.push_back(q);
  };
  for (float x = -0.3f; x <= 0.3f + 1e-4f; x += 0.01f) {
    for (float y = -0.4f; y <= 0.25f + 1e-4f; y += 0.01f) {
      if (!(x > -0.11f && x < 0.11f && y > -0.01f && y < 0.16f)) add(x, y, 0.0f);
    }
    for (float z = 0.01f; z <= 0.6f + 1e-4f; z += 0.01f) add(x, 0.25f, z);
  }
  if (occluder) {
    for (float x = -0.15f; x <= 0.15f + 1e-4f; x += 0.01f) {
      for (float z = 0.01f; z <= 0.34f + 1e-4f; z += 0.01f) add(x, -0.1f, z);
    }
  }
  std::vector<int> board;
  for (float x = -0.1f; x <= 0.1f + 1e-4f; x += 0.01f) {
    for (float y = 0.0f; y <= 0.15f + 1e-4f; y += 0.01f) {
      board.push_back(static_cast<int>(cloud.size()));
      add(x, y, 0.36f);
    }
  }
  return board;
}

}  // namespace

TEST(FreeShareUnder, TheSpaceUnderAShelfIsSeenEmptyWhatIsOverAnOccluderHasItHidden) {
  const Eigen::Vector3f camera(0.0f, kCameraY, kCameraZ);
  ss::Cloud open;
  const std::vector<int> board = boardScene(open, false);
  ASSERT_TRUE(ss::restsOnNothing(open, board, kTable, kMargin, kCell));
  const auto seen_free = ss::freeShareUnder(open, board, kTable, kMargin, ss::OccupancyMap::fromRayCasting(open, {camera}));
  ASSERT_TRUE(seen_free.has_value());
  EXPECT_GT(*seen_free, 0.5f);

  ss::Cloud hidden;
  const std::vector<int> over_occluder = boardScene(hidden, true);
  const auto behind =
      ss::freeShareUnder(hidden, over_occluder, kTable, kMargin, ss::OccupancyMap::fromRayCasting(hidden, {camera}));
  ASSERT_TRUE(behind.has_value());
  EXPECT_LT(*behind, 0.5f);

  // No room for a probe under a segment 3 cm over the table.
  ss::Cloud low;
  std::vector<int> slab;
  for (float x = 0.0f; x <= 0.05f; x += 0.01f) {
    ss::PointT p;
    p.x = x; p.y = 0.0f; p.z = 0.03f;
    slab.push_back(static_cast<int>(low.size()));
    low.push_back(p);
  }
  EXPECT_FALSE(ss::freeShareUnder(low, slab, kTable, kMargin, ss::OccupancyMap::fromRayCasting(low, {camera})));
}
