// The make_scene command-line tool: argument errors and the files it writes.

#include <gtest/gtest.h>

#include <set>

#include <algorithm>
#include <cmath>

#include <boost/filesystem.hpp>

#include "symmetry_segmentation/scene_io.h"
#include "test_support.h"

namespace ss = symmetry_segmentation;
using test_support::runCommand;
using test_support::toolPath;

namespace {

std::string makeScene(const std::string& arguments) { return toolPath("make_scene") + " " + arguments; }

/// Exit code 2 and a single line of output naming the problem.
void expectUsageError(const std::string& arguments, const std::string& mention) {
  const auto result = runCommand(makeScene(arguments));
  EXPECT_EQ(result.exit_code, 2) << arguments << "\n" << result.output;
  EXPECT_NE(result.output.find(mention), std::string::npos) << arguments << "\n" << result.output;
  EXPECT_EQ(std::count(result.output.begin(), result.output.end(), '\n'), 1) << result.output;
}

}  // namespace

TEST(MakeSceneTool, HelpAndKindList) {
  const auto help = runCommand(makeScene("--help"));
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.output.find("usage: make_scene"), std::string::npos);
  const auto kinds = runCommand(makeScene("--list-kinds"));
  EXPECT_EQ(kinds.exit_code, 0);
  for (const char* kind : {"isolated", "touching", "stacked", "occluded", "nonconvex", "clutter"}) {
    EXPECT_NE(kinds.output.find(kind), std::string::npos) << kind;
  }
}

TEST(MakeSceneTool, BadArgumentsExitWithCodeTwo) {
  const std::string dir = test_support::makeTempDir("make_scene_bad_args");
  expectUsageError("--kind pile --seed 1 --output " + dir, "unknown scene kind 'pile'");
  expectUsageError("--kind clutter --seed 1", "missing --output");
  expectUsageError("--kind clutter --output " + dir, "missing --seed");
  expectUsageError("--seed 1 --output " + dir, "missing --kind");
  expectUsageError("--kind clutter --seed abc --output " + dir, "--seed");
  expectUsageError("--kind clutter --seed -3 --output " + dir, "--seed");
  expectUsageError("--kind clutter --seed 99999999999 --output " + dir, "--seed");
  expectUsageError("--kind clutter --seed 1 --views 0 --output " + dir, "--views");
  expectUsageError("--kind clutter --seed 1 --fusion-voxel 0 --output " + dir, "--fusion-voxel");
  expectUsageError("--kind clutter --seed 1 --fusion-voxel 3mm --output " + dir, "--fusion-voxel");
  expectUsageError("--kind clutter --seed 1 --image-scale 7 --output " + dir, "--image-scale");
  expectUsageError("--kind clutter --seed 1 --output", "--output needs a value");
  expectUsageError("--kind clutter --seed 1 --colour red --output " + dir, "unknown argument '--colour'");
  expectUsageError("--kind clutter --seed 1 --single-view lidar --output " + dir, "unknown depth sensor 'lidar'");
  expectUsageError("--kind clutter --seed 1 --single-view kinect --views 2 --output " + dir, "--single-view");
  expectUsageError("--kind clutter --seed 1 --single-view --output " + dir, "unknown argument");
  EXPECT_TRUE(boost::filesystem::is_empty(dir)) << "nothing is written on bad arguments";
}

TEST(MakeSceneTool, WritesTheSameFilesForTheSameSeed) {
  const std::string first = test_support::makeTempDir("make_scene_first");
  const std::string second = test_support::makeTempDir("make_scene_second");
  const auto run_a = runCommand(makeScene("--kind stacked --seed 3 --views 3 --output " + first + "/scene"));
  ASSERT_EQ(run_a.exit_code, 0) << run_a.output;
  EXPECT_NE(run_a.output.find("points"), std::string::npos) << run_a.output;
  EXPECT_NE(run_a.output.find("5 objects"), std::string::npos) << run_a.output;
  const auto run_b = runCommand(makeScene("--output " + second + "/scene --seed 3 --kind stacked --views 3"));
  ASSERT_EQ(run_b.exit_code, 0) << run_b.output;
  for (const char* file : {"cloud.ply", "occupancy.bt", "table_plane.txt", "labels.txt", "scene_info.yaml"}) {
    const std::string a = first + "/scene/" + file;
    const std::string b = second + "/scene/" + file;
    ASSERT_TRUE(boost::filesystem::exists(a)) << a;
    EXPECT_TRUE(test_support::readTextFile(a) == test_support::readTextFile(b)) << file << " differs";
  }

  const ss::Scene scene = ss::loadScene(first + "/scene");
  EXPECT_GT(scene.size(), 50000u);
  EXPECT_EQ(scene.labels.size(), scene.size());
  EXPECT_TRUE(scene.has_normals);
  EXPECT_EQ(scene.kind, "stacked");
  EXPECT_EQ(scene.sensor_origins.size(), 3u);
  EXPECT_TRUE(scene.occupancy);
  ASSERT_TRUE(scene.table_plane);
  EXPECT_NEAR((*scene.table_plane)[2], 1.0f, 1e-6f);
}

// The scaling benchmark's knobs: a coarser fusion voxel gives fewer points, a finer one with a
// sharper camera more, over the same objects.
TEST(MakeSceneTool, FusionVoxelAndImageScaleSetTheDensity) {
  const std::string dir = test_support::makeTempDir("make_scene_density");
  ASSERT_EQ(runCommand(makeScene("--kind isolated --seed 2 --views 1 --fusion-voxel 0.008 --output " + dir + "/coarse")).exit_code, 0);
  ASSERT_EQ(runCommand(makeScene("--kind isolated --seed 2 --views 1 --fusion-voxel 0.0015 --image-scale 2 --output " + dir + "/fine")).exit_code, 0);
  const ss::Scene coarse = ss::loadScene(dir + "/coarse");
  const ss::Scene fine = ss::loadScene(dir + "/fine");
  EXPECT_GT(fine.size(), 8 * coarse.size());
  std::set<int> coarse_labels(coarse.labels.begin(), coarse.labels.end());
  std::set<int> fine_labels(fine.labels.begin(), fine.labels.end());
  EXPECT_EQ(coarse_labels, fine_labels) << "same objects";
}

// --realistic --single-view: one organized frame with the room in it, no map, no table plane.
TEST(MakeSceneTool, RealisticSingleViewWritesAnOrganizedFrame) {
  const std::string dir = test_support::makeTempDir("make_scene_single_view");
  const auto run = runCommand(makeScene("--kind touching --seed 5 --realistic --single-view realsense --output " + dir + "/scene"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("1 views"), std::string::npos) << run.output;
  EXPECT_TRUE(boost::filesystem::exists(dir + "/scene/cloud.pcd"));
  EXPECT_FALSE(boost::filesystem::exists(dir + "/scene/occupancy.bt"));
  EXPECT_FALSE(boost::filesystem::exists(dir + "/scene/table_plane.txt"));
  const ss::Scene scene = ss::loadScene(dir + "/scene");
  EXPECT_EQ(scene.cloud->width * scene.cloud->height, 640u * 480u);
  EXPECT_EQ(scene.cloud->height, 480u);
  EXPECT_EQ(scene.kind, "touching");
  // Background (label 0) far behind the objects: the wall.
  float farthest_object = 0.0f, farthest_background = 0.0f;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    const float z = scene.cloud->points[i].z;
    if (!std::isfinite(z)) continue;
    float& farthest = scene.labels[i] > 0 ? farthest_object : farthest_background;
    farthest = std::max(farthest, z);
  }
  EXPECT_GT(farthest_background, farthest_object + 0.2f);
}
