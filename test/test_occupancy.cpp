#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/occupancy_grid.h"

#include <random>

namespace ss = symmetry_segmentation;

TEST(Occupancy, ClassifiesHandBuiltMap) {
  auto tree = std::make_shared<octomap::OcTree>(0.01);
  tree->updateNode(octomap::point3d(0.105f, 0.105f, 0.505f), true);
  tree->updateNode(octomap::point3d(0.105f, 0.105f, 0.305f), false);
  ss::OccupancyMap map(tree);
  EXPECT_EQ(map.classify({0.105f, 0.105f, 0.505f}), ss::Occupancy::Occupied);
  EXPECT_EQ(map.classify({0.105f, 0.105f, 0.305f}), ss::Occupancy::Free);
  EXPECT_EQ(map.classify({0.105f, 0.105f, 0.705f}), ss::Occupancy::Unknown);
  EXPECT_EQ(map.classify({NAN, 0.0f, 0.0f}), ss::Occupancy::Unknown);
  EXPECT_EQ(map.classify({1e7f, 0.0f, 0.0f}), ss::Occupancy::Unknown);  // outside the octree's volume
  EXPECT_DOUBLE_EQ(map.resolution(), 0.01);
}

// A wall of points at z = 1 seen from the origin: space before it is free, the wall occupied,
// and the space behind it was never observed.
TEST(Occupancy, RayCastingFromSensorOrigin) {
  ss::Cloud wall;
  for (float x = -0.2f; x <= 0.2f; x += 0.005f) {
    for (float y = -0.2f; y <= 0.2f; y += 0.005f) {
      ss::PointT p;
      p.x = x; p.y = y; p.z = 1.0f;
      wall.push_back(p);
    }
  }
  ss::PointT nan_point;
  nan_point.x = nan_point.y = nan_point.z = NAN;
  wall.push_back(nan_point);  // must be skipped, not inserted
  const auto map = ss::OccupancyMap::fromRayCasting(wall, {Eigen::Vector3f::Zero()});
  EXPECT_EQ(map.classify({0.0f, 0.0f, 0.5f}), ss::Occupancy::Free);
  EXPECT_EQ(map.classify({0.05f, -0.05f, 0.9f}), ss::Occupancy::Free);
  EXPECT_EQ(map.classify({0.0f, 0.0f, 1.0f}), ss::Occupancy::Occupied);
  EXPECT_EQ(map.classify({0.0f, 0.0f, 1.2f}), ss::Occupancy::Unknown);
  EXPECT_EQ(map.classify({1.0f, 0.0f, 0.5f}), ss::Occupancy::Unknown);  // outside every ray
}

TEST(Occupancy, RayCastingUsesNearestOrigin) {
  ss::Cloud cloud;
  ss::PointT left, right;
  left.x = -1.0f; left.y = 0; left.z = 1.0f;
  right.x = 1.0f; right.y = 0; right.z = 1.0f;
  cloud.push_back(left);
  cloud.push_back(right);
  const auto map = ss::OccupancyMap::fromRayCasting(cloud, {{-1.0f, 0, 0}, {1.0f, 0, 0}});
  EXPECT_EQ(map.classify({-1.0f, 0, 0.5f}), ss::Occupancy::Free);
  EXPECT_EQ(map.classify({1.0f, 0, 0.5f}), ss::Occupancy::Free);
  EXPECT_EQ(map.classify({0.0f, 0, 0.5f}), ss::Occupancy::Unknown);  // no ray crosses the middle
}

TEST(Occupancy, SceneWithoutMapOrOriginIsAnError) {
  ss::Scene scene;
  scene.cloud = std::make_shared<ss::Cloud>();
  scene.cloud_path = "cloud.ply";
  EXPECT_THROW(ss::occupancyForScene(scene), ss::InputError);
  scene.sensor_origins.push_back(Eigen::Vector3f::Zero());
  ss::PointT p;
  p.x = 0; p.y = 0; p.z = 1;
  scene.cloud->push_back(p);
  EXPECT_EQ(ss::occupancyForScene(scene).classify({0, 0, 0.5f}), ss::Occupancy::Free);
}

// The dense cache answers exactly like the map, inside its box (where pruned free leaves span
// many voxels) and outside it (where it asks the map).
TEST(OccupancyGrid, AgreesWithTheMapEverywhere) {
  ss::Cloud wall;
  for (float x = -0.3f; x <= 0.3f; x += 0.005f) {
    for (float y = -0.3f; y <= 0.3f; y += 0.005f) {
      ss::PointT p;
      p.x = x; p.y = y; p.z = 1.0f + 0.1f * x;
      wall.push_back(p);
    }
  }
  const auto map = ss::OccupancyMap::fromRayCasting(wall, {Eigen::Vector3f(0.05f, 0.0f, 0.0f)});
  const Eigen::AlignedBox3f box(Eigen::Vector3f(-0.2f, -0.15f, 0.5f), Eigen::Vector3f(0.25f, 0.2f, 1.3f));
  const ss::OccupancyGrid grid(map, box);
  EXPECT_GT(grid.cachedCells(), 100000u);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> coordinate(-0.4f, 0.4f), depth(0.3f, 1.5f);
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < 200000; ++i) {
    const Eigen::Vector3f p(coordinate(random), coordinate(random), depth(random));
    const ss::Occupancy expected = map.classify(p);
    ASSERT_EQ(grid.classify(p), expected) << p.transpose();
    ++counts[static_cast<int>(expected)];
  }
  for (int c : counts) EXPECT_GT(c, 100);  // all three kinds were tested
  EXPECT_EQ(grid.classify({NAN, 0.0f, 1.0f}), ss::Occupancy::Unknown);

  // A box too large to cache: every query goes to the map.
  const ss::OccupancyGrid uncached(map, box, 1000);
  EXPECT_EQ(uncached.cachedCells(), 0u);
  EXPECT_EQ(uncached.classify({0.0f, 0.0f, 0.5f}), map.classify({0.0f, 0.0f, 0.5f}));
}
