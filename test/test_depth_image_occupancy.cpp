// Occupancy straight from a camera frame's depth image, against what the frame shows and against
// the ray-cast OctoMap of the same frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include <Eigen/Geometry>

#include "symmetry_segmentation/depth_image_occupancy.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/scene_io.h"
#include "test_support.h"

namespace ss = symmetry_segmentation;

namespace {

constexpr int kWidth = 240, kHeight = 180;
constexpr float kFocal = 200.0f;

// A camera at the origin looking along +z at a wall (z = 1) with a box face in front of it
// (z = 0.8 over |x|, |y| < 0.1) and a patch with no return (a dark spot: NaN pixels).
ss::Cloud wallAndBoxFrame() {
  ss::Cloud frame(kWidth, kHeight);
  for (int v = 0; v < kHeight; ++v) {
    for (int u = 0; u < kWidth; ++u) {
      const Eigen::Vector3f ray((u - kWidth / 2.0f) / kFocal, (v - kHeight / 2.0f) / kFocal, 1.0f);
      float t = 1.0f;
      if (std::fabs(0.8f * ray.x()) < 0.1f && std::fabs(0.8f * ray.y()) < 0.1f) t = 0.8f;
      ss::PointT& p = frame.at(u, v);
      p.getVector3fMap() = t * ray;
      if (u < 20 && v < 20) p.x = p.y = p.z = NAN;  // the dark spot, top left
    }
  }
  return frame;
}

std::shared_ptr<const ss::DepthImageOccupancy> occupancyOf(const ss::Cloud& frame) {
  return ss::DepthImageOccupancy::fromOrganizedCloud(frame, 0.01f);
}

}  // namespace

TEST(DepthImageOccupancy, FreeInFrontOccupiedAtTheSurfaceUnknownBehindOrUnseen) {
  const auto occupancy = occupancyOf(wallAndBoxFrame());
  ASSERT_TRUE(occupancy);
  EXPECT_LT(occupancy->reprojectionError(), 0.05f);
  EXPECT_LT(occupancy->cameraCenter().norm(), 1e-3f);
  using O = ss::Occupancy;
  EXPECT_EQ(occupancy->classify({0.0f, 0.0f, 0.5f}), O::Free);       // before the box
  EXPECT_EQ(occupancy->classify({0.0f, 0.0f, 0.795f}), O::Occupied);  // on its face
  EXPECT_EQ(occupancy->classify({0.0f, 0.0f, 0.9f}), O::Unknown);     // hidden behind it
  EXPECT_EQ(occupancy->classify({0.3f, 0.0f, 0.9f}), O::Free);        // beside it, before the wall
  EXPECT_EQ(occupancy->classify({0.3f, 0.0f, 1.0f}), O::Occupied);    // the wall
  EXPECT_EQ(occupancy->classify({0.3f, 0.0f, 1.2f}), O::Unknown);     // behind the wall
  EXPECT_EQ(occupancy->classify({5.0f, 0.0f, 1.0f}), O::Unknown);     // off the image
  EXPECT_EQ(occupancy->classify({0.0f, 0.0f, -1.0f}), O::Unknown);    // behind the camera
  EXPECT_EQ(occupancy->classify({-0.5f, -0.4f, 0.9f}), O::Unknown);   // the pixel saw nothing
  EXPECT_EQ(occupancy->classify({NAN, 0.0f, 0.5f}), O::Unknown);
}

// A frame moved into a robot's base frame answers the same: the camera is fitted, not assumed.
TEST(DepthImageOccupancy, SameAnswersAfterMovingTheFrameToABaseFrame) {
  const ss::Cloud frame = wallAndBoxFrame();
  const Eigen::Affine3f to_base = Eigen::Translation3f(0.4f, -0.2f, 1.1f) *
                                  Eigen::AngleAxisf(2.1f, Eigen::Vector3f(0.3f, -1.0f, 0.5f).normalized());
  ss::Cloud moved = frame;
  for (ss::PointT& p : moved.points) p.getVector3fMap() = to_base * p.getVector3fMap();
  const auto in_camera = occupancyOf(frame);
  const auto in_base = occupancyOf(moved);
  ASSERT_TRUE(in_camera && in_base);
  EXPECT_LT((in_base->cameraCenter() - to_base.translation()).norm(), 1e-3f);
  std::mt19937 random(3);
  std::uniform_real_distribution<float> lateral(-0.6f, 0.6f), depth(0.2f, 1.4f);
  int differing = 0, free = 0;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3f q(lateral(random), lateral(random), depth(random));
    const ss::Occupancy expected = in_camera->classify(q);
    differing += in_base->classify(to_base * q) != expected;
    free += expected == ss::Occupancy::Free;
  }
  EXPECT_GT(free, 1000);
  EXPECT_LE(differing, 20);  // float rounding at pixel borders only
}

TEST(DepthImageOccupancy, OnlyForOnePinholeCamerasImage) {
  ss::Cloud frame = wallAndBoxFrame();
  ss::Cloud unorganized = frame;
  unorganized.width = static_cast<std::uint32_t>(unorganized.size());
  unorganized.height = 1;
  EXPECT_FALSE(occupancyOf(unorganized));

  ss::Cloud shuffled = frame;  // organized in shape, but its points are not at their pixels
  std::shuffle(shuffled.points.begin(), shuffled.points.end(), std::mt19937(5));
  EXPECT_FALSE(occupancyOf(shuffled));

  ss::Cloud dark = frame;  // almost nothing returned
  for (std::size_t i = 50; i < dark.size(); ++i) dark.points[i].x = dark.points[i].y = dark.points[i].z = NAN;
  EXPECT_FALSE(occupancyOf(dark));

  ss::Cloud bare_wall = frame;  // one plane fits many cameras: none is chosen
  for (ss::PointT& p : bare_wall.points) p.getVector3fMap() /= p.z;
  EXPECT_FALSE(occupancyOf(bare_wall));

  ss::Cloud collapsed = frame;  // every pixel saw the same point: no camera fits
  for (ss::PointT& p : collapsed.points) p.x = p.y = p.z = 0.5f;
  EXPECT_FALSE(occupancyOf(collapsed));
}

// A camera frame needs neither a map nor a viewpoint; without the depth image, the ray-cast
// path still needs a sensor origin.
TEST(DepthImageOccupancy, ACameraFrameNeedsNoSensorOrigin) {
  ss::Scene scene;
  scene.cloud_path = "frame.pcd";
  scene.cloud = std::make_shared<ss::Cloud>(wallAndBoxFrame());
  const ss::OccupancyMap map = ss::occupancyForScene(scene);
  ASSERT_NE(map.depthImage(), nullptr);
  EXPECT_EQ(map.classify({0.0f, 0.0f, 0.5f}), ss::Occupancy::Free);
  ss::RayCastOptions ray_cast;
  ray_cast.from_depth_image = false;
  EXPECT_THROW(ss::occupancyForScene(scene, ray_cast), ss::InputError);
  scene.sensor_origins.push_back(Eigen::Vector3f::Zero());
  EXPECT_EQ(ss::occupancyForScene(scene, ray_cast).depthImage(), nullptr);
}

namespace {

// Share of random points around `frame` that both maps classify alike, and how many of them the
// ray-cast map calls free.
double agreementWithRayCasting(const ss::Cloud& frame, const Eigen::Vector3f& origin, std::size_t samples,
                               std::size_t& ray_cast_free) {
  const auto depth_image = occupancyOf(frame);
  if (!depth_image) return 0.0;
  ss::RayCastOptions options;
  options.resolution = 0.01;
  const ss::OccupancyMap ray_cast = ss::OccupancyMap::fromRayCasting(frame, {origin}, options);
  Eigen::AlignedBox3f box;
  for (const ss::PointT& p : frame.points) {
    if (p.getVector3fMap().allFinite()) box.extend(p.getVector3fMap());
  }
  box.extend(origin);
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::size_t agree = 0;
  ray_cast_free = 0;
  std::size_t confusion[3][3] = {};
  for (std::size_t i = 0; i < samples; ++i) {
    const Eigen::Vector3f q = box.min() + box.sizes().cwiseProduct(Eigen::Vector3f(unit(random), unit(random), unit(random)));
    const ss::Occupancy expected = ray_cast.classify(q);
    agree += depth_image->classify(q) == expected;
    ++confusion[int(expected)][int(depth_image->classify(q))];
    ray_cast_free += expected == ss::Occupancy::Free;
  }
  std::printf("  ray-cast free / occupied / unknown -> depth image free, occupied, unknown:");
  for (auto& row : confusion) std::printf("  %zu %zu %zu /", row[0], row[1], row[2]);
  std::printf("\n");
  return static_cast<double>(agree) / samples;
}

}  // namespace

TEST(DepthImageOccupancy, AgreesWithTheRayCastMapOfTheSameFrame) {
  std::size_t free = 0;
  const double agreement = agreementWithRayCasting(wallAndBoxFrame(), Eigen::Vector3f::Zero(), 100000, free);
  std::printf("synthetic frame: %.4f of points classified alike (ray-cast free: %zu)\n", agreement, free);
  EXPECT_GT(free, 10000u);
  EXPECT_GT(agreement, 0.98);
}

// The same on real Kinect frames (OSD), when ../shared is there.
TEST(DepthImageOccupancy, AgreesWithTheRayCastMapOnRealFrames) {
  if (!test_support::haveSharedData()) GTEST_SKIP() << "no ../shared/data";
  for (const char* name : {"learn0", "learn30"}) {
    const ss::Scene scene = ss::loadScene(test_support::sharedDataDir() + "/real/osd_learn/" + name + ".pcd");
    ASSERT_TRUE(scene.cloud->isOrganized());
    ASSERT_EQ(scene.sensor_origins.size(), 1u);
    const auto occupancy = occupancyOf(*scene.cloud);
    ASSERT_TRUE(occupancy);
    EXPECT_LT((occupancy->cameraCenter() - scene.sensor_origins.front()).norm(), 0.01f);
    std::size_t free = 0;
    const double agreement = agreementWithRayCasting(*scene.cloud, scene.sensor_origins.front(), 200000, free);
    std::printf("%s: reprojection error %.3f px, %.4f of points classified alike (ray-cast free: %zu)\n", name,
                occupancy->reprojectionError(), agreement, free);
    EXPECT_GT(free, 20000u);
    EXPECT_GT(agreement, 0.95);
  }
}
