// scene_to_bag and segment_bag end to end: a scene becomes a bag with the octomap_msgs type,
// and the segmented bag holds one result per cloud, stamped like it, faster than real time.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <boost/filesystem.hpp>
#include <pcl_msgs/ModelCoefficients.h>
#include <rosbag/bag.h>
#include <sensor_msgs/PointCloud2.h>
#include <rosbag/view.h>
#include <sensor_msgs/PointCloud2.h>

#include "symmetry_segmentation/SegmentedObjectArray.h"
#include "symmetry_segmentation/ros/octomap_message.h"

namespace ss = symmetry_segmentation;
namespace fs = boost::filesystem;

namespace {

int run(const std::string& command, std::string* output = nullptr) {
  const std::string log = (fs::temp_directory_path() / fs::unique_path("bag_tool_%%%%%%.log")).string();
  const int status = std::system((command + " > " + log + " 2>&1").c_str());
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  if (output) *output = text.str();
  fs::remove(log);
  return WEXITSTATUS(status);
}

}  // namespace

TEST(BagTools, SceneToBagThenSegmentBag) {
  const fs::path dir = fs::temp_directory_path() / fs::unique_path("bag_tools_%%%%%%");
  fs::create_directories(dir);
  const std::string scene_bag = (dir / "scene.bag").string();
  const std::string result_bag = (dir / "segmented.bag").string();
  std::string output;
  ASSERT_EQ(run(std::string(TOOLS_DIR) + "/scene_to_bag " + SOURCE_DIR + "/data/default_scene --output " + scene_bag +
                    " --voxel 0.006 --clouds 2 --rate 0.25 --full-octomap",
                &output),
            0)
      << output;

  {
    rosbag::Bag bag(scene_bag, rosbag::bagmode::Read);
    rosbag::View view(bag);
    std::set<std::string> topics;
    for (const auto* connection : view.getConnections()) {
      topics.insert(connection->topic);
      if (connection->topic == "/octomap_binary") {
        EXPECT_EQ(connection->datatype, "octomap_msgs/Octomap");
        EXPECT_EQ(connection->md5sum, "9a45536b45c5e409cd49f04bb2d9999f");
        EXPECT_EQ(connection->header->at("latching"), "1");
      }
    }
    EXPECT_EQ(topics, (std::set<std::string>{"/kinfu/cloud", "/octomap_binary", "/table_plane", "/tf_static"}));
    std::size_t maps = 0;
    for (const auto& instance : view) {
      if (auto plane = instance.instantiate<pcl_msgs::ModelCoefficients>()) {
        EXPECT_EQ(plane->header.frame_id, "map");
        EXPECT_EQ(plane->values, (std::vector<float>{0, 0, 1, 0})) << "data/default_scene/table_plane.txt";
      }
      if (auto map = instance.instantiate<ss::OctomapMessage>()) {
        EXPECT_FALSE(map->binary);  // --full-octomap
        EXPECT_EQ(map->id, "OcTree");
        EXPECT_EQ(map->header.frame_id, "map");
        ++maps;
      }
    }
    EXPECT_EQ(maps, 1u);
  }

  ASSERT_EQ(run(std::string(TOOLS_DIR) + "/segment_bag " + scene_bag + " --output " + result_bag +
                    " --sensor-frame camera",
                &output),
            0)
      << output;
  EXPECT_NE(output.find("segmented 2 clouds (0 failed)"), std::string::npos) << output;
  // "... bag spans 4.05 s (3.5x real time) ...": clouds 4 s apart take about 0.6 s each.
  const auto close = output.find("x real time");
  ASSERT_NE(close, std::string::npos) << output;
  const auto open = output.rfind('(', close);
  ASSERT_NE(open, std::string::npos) << output;
#if defined(__SANITIZE_ADDRESS__)
  // The sanitized -O1 build (scripts/test --sanitize) runs several times slower: only a rate.
  EXPECT_GT(std::stod(output.substr(open + 1, close - open - 1)), 0.0) << output;
#else
  EXPECT_GT(std::stod(output.substr(open + 1, close - open - 1)), 1.0) << output;
#endif
  // An up frame the bag's tf does not know fails every cloud, with the reason, and exit 1.
  EXPECT_EQ(run(std::string(TOOLS_DIR) + "/segment_bag " + scene_bag + " --output " + (dir / "no_up.bag").string() +
                    " --sensor-frame camera --up-frame no_such_frame",
                &output),
            1)
      << output;
  EXPECT_NE(output.find("no_such_frame"), std::string::npos) << output;
  EXPECT_NE(output.find("segmented 0 clouds (2 failed)"), std::string::npos) << output;
  rosbag::Bag bag(result_bag, rosbag::bagmode::Read);
  rosbag::View view(bag, rosbag::TopicQuery("/segmentation/objects"));
  std::vector<ros::Time> stamps;
  for (const auto& instance : view) {
    const auto objects = instance.instantiate<ss::SegmentedObjectArray>();
    ASSERT_TRUE(objects);
    EXPECT_GE(objects->objects.size(), 5u) << "the bundled scene has 12 objects";
    EXPECT_EQ(objects->header.frame_id, "map");
    stamps.push_back(objects->header.stamp);
  }
  EXPECT_EQ(stamps, (std::vector<ros::Time>{ros::Time(1000.05), ros::Time(1004.05)}));
  rosbag::View clouds(bag, rosbag::TopicQuery("/segmentation/segmented_cloud"));
  EXPECT_EQ(clouds.size(), 2u);
  rosbag::View markers(bag, rosbag::TopicQuery("/segmentation/symmetry_markers"));
  EXPECT_EQ(markers.size(), 2u);
  fs::remove_all(dir);
}

// A single camera frame (organized, no normals, no map) becomes a bag as a camera driver would
// send it - organized, without normal fields, no OctoMap - and segments from it alone.
TEST(BagTools, ACameraFrameWithoutAMap) {
  const fs::path dir = fs::temp_directory_path() / fs::unique_path("bag_camera_%%%%%%");
  fs::create_directories(dir);
  std::string output;
  ASSERT_EQ(run(std::string(TOOLS_DIR) + "/make_scene --kind isolated --seed 43 --single-view kinect --output " +
                    (dir / "frame").string(),
                &output),
            0)
      << output;
  const std::string frame_bag = (dir / "frame.bag").string();
  ASSERT_EQ(run(std::string(TOOLS_DIR) + "/scene_to_bag " + (dir / "frame").string() + " --output " + frame_bag +
                    " --clouds 2 --rate 30",
                &output),
            0)
      << output;
  EXPECT_NE(output.find("(640 x 480)"), std::string::npos) << output;
  EXPECT_NE(output.find("no OctoMap"), std::string::npos) << output;
  {
    rosbag::Bag bag(frame_bag, rosbag::bagmode::Read);
    rosbag::View view(bag);
    std::set<std::string> topics;
    for (const auto* connection : view.getConnections()) topics.insert(connection->topic);
    EXPECT_EQ(topics, (std::set<std::string>{"/kinfu/cloud", "/tf_static"}));
    for (const auto& instance : view) {
      if (auto cloud = instance.instantiate<sensor_msgs::PointCloud2>()) {
        EXPECT_EQ(cloud->width, 640u);
        EXPECT_EQ(cloud->height, 480u);
        for (const auto& field : cloud->fields) EXPECT_NE(field.name, "normal_x");
      }
    }
  }
  const std::string result_bag = (dir / "segmented.bag").string();
  ASSERT_EQ(run(std::string(TOOLS_DIR) + "/segment_bag " + frame_bag + " --output " + result_bag, &output), 0)
      << output;
  EXPECT_NE(output.find("segmented 2 clouds (0 failed)"), std::string::npos) << output;
  rosbag::Bag bag(result_bag, rosbag::bagmode::Read);
  rosbag::View objects(bag, rosbag::TopicQuery("/segmentation/objects"));
  ASSERT_EQ(objects.size(), 2u);
  for (const auto& instance : objects) {
    EXPECT_GE(instance.instantiate<ss::SegmentedObjectArray>()->objects.size(), 2u) << "5 objects on the table";
  }
  fs::remove_all(dir);
}

TEST(BagTools, SegmentBagFailsClearlyOnAMissingFile) {
  std::string output;
  EXPECT_EQ(run(std::string(TOOLS_DIR) + "/segment_bag /nonexistent.bag --output /tmp/never.bag", &output), 1);
  EXPECT_NE(output.find("segment_bag: error:"), std::string::npos) << output;
}

// Malformed numbers once aborted scene_to_bag (an uncaught std::stoi exception).
TEST(BagTools, BadNumbersAreUsageErrors) {
  const std::string scene = std::string(SOURCE_DIR) + "/data/default_scene";
  for (const char* option : {"--clouds abc", "--clouds 0", "--rate 1e999", "--rate", "--voxel 1cm"}) {
    std::string output;
    EXPECT_EQ(run(std::string(TOOLS_DIR) + "/scene_to_bag " + scene + " --output /tmp/never.bag " + option, &output), 2)
        << option;
    EXPECT_NE(output.find("scene_to_bag: "), std::string::npos) << output;
  }
  std::string output;
  EXPECT_EQ(run(std::string(TOOLS_DIR) + "/segment_bag in.bag --output out.bag --set nokey", &output), 2);
  EXPECT_NE(output.find("--set expects section.key=value"), std::string::npos) << output;
}
