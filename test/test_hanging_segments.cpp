// restsOnNothing: a shelf over the table rests on nothing; an object on the table, one stacked
// on another and a ball whose underside is hidden from view do.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

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
  EXPECT_FALSE(ss::restsOnNothing(cloud, shelf, ss::PlaneCoefficients::Zero(), kMargin, kCell));
  EXPECT_FALSE(ss::restsOnNothing(cloud, {-1, static_cast<int>(cloud.size())}, kTable, kMargin, kCell));
}
