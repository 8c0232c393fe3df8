#include <gtest/gtest.h>

#include "symmetry_segmentation/background_surfaces.h"

namespace ss = symmetry_segmentation;

namespace {

void addRectangle(ss::Cloud& cloud, const Eigen::Vector3f& corner, const Eigen::Vector3f& side_a,
                  const Eigen::Vector3f& side_b, float step) {
  for (float a = 0.0f; a <= side_a.norm(); a += step) {
    for (float b = 0.0f; b <= side_b.norm(); b += step) {
      ss::PointT p;
      p.getVector3fMap() = corner + a * side_a.normalized() + b * side_b.normalized();
      cloud.push_back(p);
    }
  }
}

// z is up, the table top z = 0 over y < 0.6; the region is y < 0.65 (the grown polygon), z < 0.5.
std::vector<bool> inRegion(const ss::Cloud& cloud) {
  std::vector<bool> in(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) in[i] = cloud[i].y < 0.65f && cloud[i].z < 0.5f;
  return in;
}

constexpr float kStep = 0.015f;

}  // namespace

TEST(BackgroundSurfaces, AWallReachingOverTheTableIsBackgroundABoxFaceIsNot) {
  ss::Cloud cloud;
  // A wall 3 cm behind the table's edge, 1.2 m wide, 0.8 m high: its foot lies in the region.
  addRectangle(cloud, {-0.6f, 0.63f, 0.02f}, {1.2f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.8f}, kStep);
  const std::size_t wall = cloud.size();
  // A box's front face, 30 x 25 cm, on the table.
  addRectangle(cloud, {-0.15f, 0.2f, 0.02f}, {0.3f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.25f}, kStep);
  const std::vector<bool> all(cloud.size(), true);
  ss::BackgroundSurfaceParams params;
  const std::vector<bool> background = ss::backgroundSurfacePoints(cloud, all, inRegion(cloud), params);
  std::size_t wall_found = 0, box_found = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) (i < wall ? wall_found : box_found) += background[i];
  EXPECT_GT(wall_found, 0.9 * wall);
  EXPECT_EQ(box_found, 0u);

  params.max_object_extent = 0.0f;  // off
  const std::vector<bool> none = ss::backgroundSurfacePoints(cloud, all, inRegion(cloud), params);
  EXPECT_EQ(std::count(none.begin(), none.end(), true), 0);
}

TEST(BackgroundSurfaces, WhatStaysInsideTheRegionOrIsNoCandidateIsKept) {
  ss::Cloud cloud;
  // A 60 cm board lying on the table, all of it inside the region: large, but no wall.
  addRectangle(cloud, {-0.3f, 0.1f, 0.03f}, {0.6f, 0.0f, 0.0f}, {0.0f, 0.3f, 0.0f}, kStep);
  const std::vector<bool> all(cloud.size(), true);
  ss::BackgroundSurfaceParams params;
  auto background = ss::backgroundSurfacePoints(cloud, all, inRegion(cloud), params);
  EXPECT_EQ(std::count(background.begin(), background.end(), true), 0);

  // The wall again, but its points are not candidates (the caller left them out).
  ss::Cloud wall_cloud;
  addRectangle(wall_cloud, {-0.6f, 0.63f, 0.02f}, {1.2f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.8f}, kStep);
  const std::vector<bool> none(wall_cloud.size(), false);
  background = ss::backgroundSurfacePoints(wall_cloud, none, inRegion(wall_cloud), params);
  EXPECT_EQ(std::count(background.begin(), background.end(), true), 0);
}

TEST(BackgroundSurfaces, APlaneSlicingThroughARowOfObjectsIsNoSurface) {
  // Eight cans of 8 cm touching in a row across the region's edge, 64 cm long: a horizontal
  // plane through them meets only thin rings, not a surface.
  ss::Cloud cloud;
  for (int can = 0; can < 8; ++can) {
    const Eigen::Vector2f centre(-0.28f + 0.08f * static_cast<float>(can), 0.6f);
    for (float z = 0.02f; z < 0.15f; z += kStep) {
      for (int k = 0; k < 24; ++k) {
        const float angle = static_cast<float>(k) * 2.0f * static_cast<float>(M_PI) / 24.0f;
        ss::PointT p;
        p.x = centre.x() + 0.04f * std::cos(angle);
        p.y = centre.y() + 0.04f * std::sin(angle);
        p.z = z;
        cloud.push_back(p);
      }
    }
  }
  // Tilt the row so that some of it leaves the region.
  for (auto& p : cloud.points) p.y += 0.2f * p.x;
  const std::vector<bool> all(cloud.size(), true);
  const auto background = ss::backgroundSurfacePoints(cloud, all, inRegion(cloud), ss::BackgroundSurfaceParams());
  EXPECT_EQ(std::count(background.begin(), background.end(), true), 0);
}
