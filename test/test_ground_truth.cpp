// Ground truth from OSD label fields, the table band, and evaluate_segmentation on OSD-style
// frames (hand-built PCDs with a label field; the real OSD learn frames when ../shared exists).
#include <gtest/gtest.h>

#include <cstdint>
#include <regex>
#include <string>
#include <vector>

#include <boost/filesystem.hpp>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/evaluation/ground_truth.h"
#include "symmetry_segmentation/evaluation/segmentation_metric.h"
#include "test_support.h"

namespace ss = symmetry_segmentation;
using test_support::makeTempDir;
using test_support::runCommand;
using test_support::toolPath;

namespace {

using OsdCloud = pcl::PointCloud<pcl::PointXYZRGBL>;

void addPoint(OsdCloud& cloud, float x, float y, float z, std::uint32_t label) {
  pcl::PointXYZRGBL point;
  point.x = x;
  point.y = y;
  point.z = z;
  point.r = point.g = point.b = 128;
  point.label = label;
  cloud.push_back(point);
}

// An OSD-style frame: a table (label 1) at z = `table_z`, a box (labels 20) and a second box
// whose sides are label 31 and whose top is label 32 (two visible pieces of one object, as mOSD
// labels an occluded object), plus invalid NaN points (label 0). 8 cm boxes 22 cm apart, surfaces
// on a 1 cm grid from 2 cm above the table.
OsdCloud osdFrame(float table_z = 0.0f) {
  OsdCloud cloud;
  for (int i = -15; i <= 25; ++i)
    for (int j = -15; j <= 15; ++j) addPoint(cloud, 0.02f * i, 0.02f * j, table_z, 1);
  const float centres[2] = {0.0f, 0.3f};
  for (int box = 0; box < 2; ++box)
    for (int i = -4; i <= 4; ++i)
      for (int j = -4; j <= 4; ++j)
        for (int k = 2; k <= 10; ++k) {
          const bool side = i == -4 || i == 4 || j == -4 || j == 4;
          if (!side && k != 10) continue;
          const std::uint32_t label = box == 0 ? 20 : (k == 10 ? 32 : 31);
          addPoint(cloud, centres[box] + 0.01f * i, 0.01f * j, table_z + 0.01f * k, label);
        }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int n = 0; n < 10; ++n) addPoint(cloud, nan, nan, nan, 0);
  cloud.sensor_origin_ = Eigen::Vector4f(0.1f, -0.6f, 0.6f + table_z, 0.0f);
  return cloud;
}

void writeFrame(const std::string& path, const OsdCloud& cloud) {
  ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(path, cloud), 0) << path;
}

std::string tool() { return toolPath("evaluate_segmentation"); }

// "| method | sigma | ... |" table rows are hard to pin down; the tool's stderr names found objects.
std::vector<std::string> progressLines(const std::string& output) {
  std::vector<std::string> found;
  const std::regex line(R"(^(\S+): euclidean: (\d+) segments, (\d+)/(\d+) objects found.*$)");
  std::istringstream in(output);
  for (std::string text; std::getline(in, text);) {
    std::smatch match;
    if (std::regex_match(text, match, line)) found.push_back(match[1].str() + " " + match[3].str() + "/" + match[4].str());
  }
  return found;
}

}  // namespace

TEST(GroundTruth, OsdLabelsAtObjectAndPartLevel) {
  const std::vector<std::uint32_t> field = {0, 1, 9, 12, 20, 21, 29, 30, 35, 117};
  EXPECT_EQ(ss::osdGroundTruth(field, false), (std::vector<int>{0, 0, 0, 0, 2, 2, 2, 3, 3, 11}));
  EXPECT_EQ(ss::osdGroundTruth(field, true), (std::vector<int>{0, 0, 0, 0, 20, 21, 29, 30, 35, 117}));
}

TEST(GroundTruth, OsdCategoriesFollowTheDataSetsRanges) {
  EXPECT_EQ(ss::osdCategory("learn0"), "boxes");
  EXPECT_EQ(ss::osdCategory("learn16"), "boxes");
  EXPECT_EQ(ss::osdCategory("learn17"), "stacked");
  EXPECT_EQ(ss::osdCategory("learn25"), "occluded");
  EXPECT_EQ(ss::osdCategory("learn44"), "cylindric");
  EXPECT_EQ(ss::osdCategory("learn45"), "");
  EXPECT_EQ(ss::osdCategory("test15"), "boxes");
  EXPECT_EQ(ss::osdCategory("test16"), "stacked");
  EXPECT_EQ(ss::osdCategory("test43"), "mixed");
  EXPECT_EQ(ss::osdCategory("test65"), "complex");
  EXPECT_EQ(ss::osdCategory("clutter_3"), "");
  EXPECT_EQ(ss::osdCategory("learn"), "");
}

TEST(GroundTruth, IgnoredPointsLeaveObjectsAndSegments) {
  // Object 1 = points 2-4; points 1 and 5 are ignored, point 0 is background.
  const std::vector<int> labels = {0, ss::kIgnoredLabel, 1, 1, 1, ss::kIgnoredLabel};
  const ss::SceneOverlap overlap = ss::computeOverlap(labels, {{1, 2, 3, 4, 5}, {0, 2, 3, 4}, {1, 5}});
  ASSERT_EQ(overlap.object_labels, std::vector<int>{1});
  ASSERT_EQ(overlap.segment_best_iou.size(), 3u);
  EXPECT_DOUBLE_EQ(overlap.segment_best_iou[0], 1.0);          // 3 / 3 once 1 and 5 are out
  EXPECT_DOUBLE_EQ(overlap.segment_best_iou[1], 3.0 / 4.0);    // the background point still counts
  EXPECT_DOUBLE_EQ(overlap.segment_best_iou[2], 0.0);          // nothing but ignored points
  EXPECT_EQ(ss::countMatches(overlap, 0.9).segments, 3u);
}

TEST(GroundTruth, TableBandIgnoresPointsNearTheFittedTablePlane) {
  const std::string dir = makeTempDir("ground_truth_band");
  OsdCloud cloud = osdFrame(0.5f);
  // A few stray "table" pixels on an object's top, as annotators leave them: the fit ignores them.
  for (int n = 0; n < 5; ++n) addPoint(cloud, 0.0f, 0.005f * n, 0.6f, 1);
  writeFrame(dir + "/learn3.pcd", cloud);

  const ss::Scene plain = ss::loadLabelledScene(dir + "/learn3.pcd", {});
  EXPECT_EQ(plain.kind, "boxes");
  ASSERT_EQ(plain.labels.size(), cloud.size());
  ss::GroundTruthOptions options;
  options.table_band = 0.025;  // the table and the boxes' lowest rows (2 cm above it)
  const ss::Scene banded = ss::loadLabelledScene(dir + "/learn3.pcd", options);
  std::size_t ignored = 0, bottom_rows = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const float height = cloud[i].z - 0.5f;
    const bool near = std::isfinite(height) && height < 0.025f;
    if (near && cloud[i].label >= 20) ++bottom_rows;
    EXPECT_EQ(banded.labels[i] == ss::kIgnoredLabel, near) << "point " << i << " at height " << height;
    if (!near) EXPECT_EQ(banded.labels[i], plain.labels[i]);
    ignored += banded.labels[i] == ss::kIgnoredLabel;
  }
  EXPECT_GT(bottom_rows, 0u);
  EXPECT_EQ(ignored, 41u * 31u + bottom_rows);
}

TEST(GroundTruth, TableBandNeedsATable) {
  const std::string dir = makeTempDir("ground_truth_no_table");
  OsdCloud cloud = osdFrame();
  for (auto& point : cloud) {
    if (point.label == 1) point.label = 20;
  }
  writeFrame(dir + "/learn1.pcd", cloud);
  ss::GroundTruthOptions options;
  options.table_band = 0.015;
  EXPECT_THROW(ss::loadLabelledScene(dir + "/learn1.pcd", options), ss::InputError);
}

TEST(GroundTruth, EvaluateSegmentationReadsOsdFramesAtObjectAndPartLevel) {
  const std::string dir = makeTempDir("ground_truth_tool");
  boost::filesystem::create_directories(dir + "/frames");
  writeFrame(dir + "/frames/learn10.pcd", osdFrame());
  writeFrame(dir + "/frames/learn2.pcd", osdFrame());

  // Euclidean clustering separates the two boxes: both objects found in each frame.
  const auto objects = runCommand(tool() + " " + dir + "/frames --method euclidean --sigma 0.9");
  ASSERT_EQ(objects.exit_code, 0) << objects.output;
  EXPECT_EQ(progressLines(objects.output), (std::vector<std::string>{"learn2 2/2", "learn10 2/2"}))
      << objects.output;
  EXPECT_NE(objects.output.find("boxes"), std::string::npos) << "kind from the frame's name\n" << objects.output;

  // At part level the second box is two objects (sides, top); one cluster matches neither well.
  const auto parts = runCommand(tool() + " " + dir + "/frames/learn2.pcd --method euclidean --osd-parts");
  ASSERT_EQ(parts.exit_code, 0) << parts.output;
  EXPECT_EQ(progressLines(parts.output), (std::vector<std::string>{"learn2 1/3"})) << parts.output;

  const auto bad_band = runCommand(tool() + " " + dir + "/frames --method euclidean --table-band -1");
  EXPECT_EQ(bad_band.exit_code, 2) << bad_band.output;
  EXPECT_NE(bad_band.output.find("--table-band"), std::string::npos) << bad_band.output;
}

TEST(GroundTruth, RealOsdLearnFramesHaveObjectsAndTables) {
  if (!test_support::haveSharedData()) GTEST_SKIP() << "no ../shared/data";
  const std::string frame = test_support::sharedDataDir() + "/real/osd_learn/learn33.pcd";
  if (!boost::filesystem::exists(frame)) GTEST_SKIP() << "no " << frame;
  ss::GroundTruthOptions options;
  options.table_band = 0.015;
  const ss::Scene scene = ss::loadLabelledScene(frame, options);
  EXPECT_EQ(scene.kind, "cylindric");
  EXPECT_EQ(scene.size(), 640u * 480u);
  const ss::SceneOverlap overlap = ss::computeOverlap(scene.labels, std::vector<std::vector<int>>{});
  EXPECT_GE(overlap.object_labels.size(), 2u);
  EXPECT_LE(overlap.object_labels.size(), 5u);  // 2-5 objects a frame (the data set's README)
  const std::size_t ignored = std::count(scene.labels.begin(), scene.labels.end(), ss::kIgnoredLabel);
  EXPECT_GT(ignored, 10000u) << "the table's points within 1.5 cm of its plane";
}
