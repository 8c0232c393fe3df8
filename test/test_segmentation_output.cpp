#include <gtest/gtest.h>

#include <set>

#include <boost/filesystem.hpp>

#include "symmetry_segmentation/segmentation_output.h"
#include "test_clouds.h"
#include "test_support.h"

namespace ss = symmetry_segmentation;

TEST(SegmentationOutput, ColoursAreDistinctAndReproducible) {
  std::set<std::tuple<int, int, int>> seen;
  for (std::size_t i = 0; i < 24; ++i) {
    const Eigen::Vector3i c = ss::segmentColor(i);
    EXPECT_TRUE((c.array() >= 0).all() && (c.array() <= 255).all());
    EXPECT_NE(c, Eigen::Vector3i(150, 150, 150));  // never the "no segment" grey
    seen.insert({c.x(), c.y(), c.z()});
    EXPECT_EQ(c, ss::segmentColor(i));
  }
  EXPECT_EQ(seen.size(), 24u);
}

TEST(SegmentationOutput, FirstSegmentWinsAndOthersStayGrey) {
  ss::Cloud cloud;
  test_clouds::addTable(cloud, 0.02f, 0.01f);  // 25 points
  ss::Segment a, b;
  a.indices = {0, 1, 2};
  b.indices = {2, 3};
  const auto colored = ss::colorBySegment(cloud, {a, b});
  ASSERT_EQ(colored.size(), cloud.size());
  const Eigen::Vector3i first = ss::segmentColor(0), second = ss::segmentColor(1);
  EXPECT_EQ(colored.points[2].r, first.x());
  EXPECT_EQ(colored.points[3].g, second.y());
  EXPECT_EQ(colored.points[4].r, 150);
  EXPECT_EQ(colored.points[4].x, cloud.points[4].x);
}

TEST(SegmentationOutput, RendersAPictureFromTheSensorSide) {
  ss::Scene scene;
  scene.cloud = std::make_shared<ss::Cloud>();
  test_clouds::addTable(*scene.cloud, 0.3f, 0.01f);
  const auto box_begin = static_cast<int>(scene.cloud->size());
  test_clouds::addBox(*scene.cloud, {0, 0, 0}, {0.1f, 0.1f, 0.1f}, 0.005f);
  scene.table_plane = ss::PlaneCoefficients(0, 0, 1, 0);
  scene.sensor_origins.push_back({0.0f, -0.6f, 0.6f});
  ss::Segment box;
  for (int i = box_begin; i < static_cast<int>(scene.cloud->size()); ++i) box.indices.push_back(i);

  const ss::View view = ss::defaultView(scene, {box});
  EXPECT_TRUE(view.eye.isApprox(scene.sensor_origins[0]));
  EXPECT_NEAR(view.target.x(), 0.05f, 0.01f);  // the box's centre
  EXPECT_GT(view.up.z(), 0.99f);

  const std::string path = test_support::makeTempDir("render") + "/picture.png";
  ss::renderPng(ss::colorBySegment(*scene.cloud, {box}), view, path, ss::segmentedPoints({box}), 320, 240);
  const std::string png = test_support::readTextFile(path);
  ASSERT_GT(png.size(), 500u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
}
