// The octomap_msgs/Octomap stand-in: identity on the wire, serialisation, tree conversions.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>

#include <Eigen/Geometry>

#include <boost/make_shared.hpp>
#include <octomap/ColorOcTree.h>
#include <octomap/OcTree.h>
#include <octomap/OcTreeStamped.h>
#include <ros/serialization.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/ros/octomap_conversion.h"
#include "symmetry_segmentation/ros/octomap_message.h"

namespace ss = symmetry_segmentation;
namespace mt = ros::message_traits;

namespace {

// Occupied slab at z = 0.5, free space between it and the origin.
template <class Tree>
void fillScene(Tree& tree) {
  octomap::Pointcloud points;
  for (double x = -0.2; x <= 0.2; x += 0.02) {
    for (double y = -0.2; y <= 0.2; y += 0.02) points.push_back(x, y, 0.5);
  }
  tree.insertPointCloud(points, octomap::point3d(0, 0, 0));
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream content;
  content << in.rdbuf();
  return content.str();
}

void expectSameOccupancy(const std::shared_ptr<octomap::OcTree>& tree) {
  ASSERT_TRUE(tree);
  const ss::OccupancyMap map(tree);
  EXPECT_EQ(map.classify({0.0f, 0.0f, 0.5f}), ss::Occupancy::Occupied);
  EXPECT_EQ(map.classify({0.0f, 0.0f, 0.25f}), ss::Occupancy::Free);
  EXPECT_EQ(map.classify({0.0f, 0.0f, 0.8f}), ss::Occupancy::Unknown);
  EXPECT_EQ(map.classify({1.0f, 1.0f, -1.0f}), ss::Occupancy::Unknown);
}

}  // namespace

TEST(OctomapMessage, IdentifiesAsOctomapMsgsOctomap) {
  EXPECT_STREQ(mt::DataType<ss::OctomapMessage>::value(), "octomap_msgs/Octomap");
  EXPECT_STREQ(mt::MD5Sum<ss::OctomapMessage>::value(), "9a45536b45c5e409cd49f04bb2d9999f");
  const std::string definition = mt::Definition<ss::OctomapMessage>::value();
  EXPECT_EQ(definition.rfind("# A 3D map in binary format, as Octree\nHeader header\n", 0), 0u);
  EXPECT_NE(definition.find("\nint8[] data\n"), std::string::npos);
  EXPECT_NE(definition.find("MSG: std_msgs/Header\n"), std::string::npos);
  // A copy: EXPECT_TRUE binds a reference to ROS's in-class constant, which has no definition
  // to link against unless the optimiser folds it (the -O1 sanitizer build does not).
  const bool has_header = mt::HasHeader<ss::OctomapMessage>::value;
  EXPECT_TRUE(has_header);
  ss::OctomapMessage message;
  message.header.frame_id = "map";
  message.header.stamp = ros::Time(12, 34);
  EXPECT_EQ(*mt::frameId(message), "map");
  EXPECT_EQ(*mt::timeStamp(message), ros::Time(12, 34));
}

TEST(OctomapMessage, SerialisationRoundTripsEveryField) {
  ss::OctomapMessage message;
  message.header.seq = 7;
  message.header.stamp = ros::Time(100, 5);
  message.header.frame_id = "odom";
  message.binary = true;
  message.id = "OcTree";
  message.resolution = 0.025;
  message.data = {1, -2, 3, 127, -128};
  const uint32_t length = ros::serialization::serializationLength(message);
  // header (4 + 8 + 4 + 4) + bool 1 + string (4 + 6) + float64 8 + int8[] (4 + 5)
  EXPECT_EQ(length, 4u + 8u + 4u + 4u + 1u + 10u + 8u + 9u);
  boost::shared_array<uint8_t> buffer(new uint8_t[length]);
  ros::serialization::OStream out(buffer.get(), length);
  ros::serialization::serialize(out, message);
  ss::OctomapMessage copy;
  ros::serialization::IStream in(buffer.get(), length);
  ros::serialization::deserialize(in, copy);
  EXPECT_EQ(copy.header.seq, 7u);
  EXPECT_EQ(copy.header.stamp, ros::Time(100, 5));
  EXPECT_EQ(copy.header.frame_id, "odom");
  EXPECT_TRUE(copy.binary);
  EXPECT_EQ(copy.id, "OcTree");
  EXPECT_DOUBLE_EQ(copy.resolution, 0.025);
  EXPECT_EQ(copy.data, message.data);
}

TEST(OctomapConversion, BinaryMessageKeepsOccupancy) {
  octomap::OcTree tree(0.02);
  fillScene(tree);
  const ss::OctomapMessage message = ss::binaryMessageFromTree(tree);
  EXPECT_TRUE(message.binary);
  EXPECT_EQ(message.id, "OcTree");
  EXPECT_DOUBLE_EQ(message.resolution, 0.02);
  const auto restored = ss::occupancyFromMessage(message);
  EXPECT_DOUBLE_EQ(restored->getResolution(), 0.02);
  EXPECT_EQ(restored->getNumLeafNodes(), tree.getNumLeafNodes());
  expectSameOccupancy(restored);
}

TEST(OctomapConversion, FullMessageKeepsOccupancy) {
  octomap::OcTree tree(0.02);
  fillScene(tree);
  const ss::OctomapMessage message = ss::fullMessageFromTree(tree);
  EXPECT_FALSE(message.binary);
  EXPECT_EQ(message.id, "OcTree");
  const auto restored = ss::occupancyFromMessage(message);
  EXPECT_EQ(restored->size(), tree.size());
  expectSameOccupancy(restored);
}

TEST(OctomapConversion, FullColorTreeBecomesOccupancy) {
  octomap::ColorOcTree tree(0.02);
  fillScene(tree);
  const ss::OctomapMessage message = ss::fullMessageFromTree(tree);
  EXPECT_EQ(message.id, "ColorOcTree");
  expectSameOccupancy(ss::occupancyFromMessage(message));
}

TEST(OctomapConversion, OtherTreeTypesAreAClearError) {
  octomap::OcTreeStamped tree(0.02);
  fillScene(tree);
  const ss::OctomapMessage message = ss::fullMessageFromTree(tree);
  EXPECT_EQ(message.id, "OcTreeStamped");
  try {
    ss::occupancyFromMessage(message);
    FAIL() << "an OcTreeStamped was accepted";
  } catch (const ss::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("unsupported tree type"), std::string::npos) << error.what();
  }
}

TEST(OctomapConversion, UnknownIdsEmptyDataAndBadResolutionAreErrors) {
  octomap::OcTree tree(0.02);
  fillScene(tree);
  ss::OctomapMessage message = ss::fullMessageFromTree(tree);
  message.id = "NoSuchTree";
  EXPECT_THROW(ss::occupancyFromMessage(message), ss::InputError);
  message = ss::binaryMessageFromTree(tree);
  message.id = "NoSuchTree";
  EXPECT_THROW(ss::occupancyFromMessage(message), ss::InputError);
  message = ss::binaryMessageFromTree(tree);
  message.data.clear();
  EXPECT_THROW(ss::occupancyFromMessage(message), ss::InputError);
  message = ss::binaryMessageFromTree(tree);
  message.resolution = 0.0;
  EXPECT_THROW(ss::occupancyFromMessage(message), ss::InputError);
  // Bytes that are no tree: truncated tree data runs out and is reported, not half-read.
  message = ss::binaryMessageFromTree(tree);
  message.data.resize(message.data.size() / 2);
  EXPECT_THROW(ss::occupancyFromMessage(message), ss::InputError);
  message = ss::fullMessageFromTree(tree);
  message.data.resize(message.data.size() / 2);
  EXPECT_THROW(ss::occupancyFromMessage(message), ss::InputError);
}

TEST(OctomapConversion, ResampledMapAnswersInTheTargetFrame) {
  // Source frame "odom"; target frame rotated a quarter turn about z and shifted by whole voxels:
  // a point p in the target is source_to_target.inverse() * p in the source.
  auto source = std::make_shared<octomap::OcTree>(0.02);
  fillScene(*source);
  Eigen::Isometry3d source_to_target = Eigen::Isometry3d::Identity();
  source_to_target.rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  source_to_target.pretranslate(Eigen::Vector3d(1.0, -0.4, 0.2));
  const Eigen::AlignedBox3d region(Eigen::Vector3d(0.5, -0.9, 0.0), Eigen::Vector3d(1.5, 0.1, 1.0));
  const auto moved = ss::resampleOccupancy(*source, source_to_target, region);
  ASSERT_TRUE(moved);
  EXPECT_DOUBLE_EQ(moved->getResolution(), 0.02);
  const ss::OccupancyMap before(source), after(moved);
  int compared = 0;
  // Voxel centres (the motion maps them onto source voxel centres, far from any boundary).
  for (double x = 0.51; x < 1.5; x += 0.06) {
    for (double y = -0.89; y < 0.1; y += 0.04) {
      for (double z = 0.01; z < 1.0; z += 0.02) {
        const Eigen::Vector3d in_target(x, y, z);
        const Eigen::Vector3d in_source = source_to_target.inverse() * in_target;
        ASSERT_EQ(after.classify(in_target.cast<float>()), before.classify(in_source.cast<float>()))
            << "at " << in_target.transpose();
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 10000);
  // The slab at source z = 0.5 is at target z = 0.7 (voxel centres below).
  ASSERT_EQ(before.classify({0.01f, 0.01f, 0.51f}), ss::Occupancy::Occupied);
  EXPECT_EQ(after.classify({0.99f, -0.39f, 0.71f}), ss::Occupancy::Occupied);
  ASSERT_EQ(before.classify({0.01f, 0.01f, 0.25f}), ss::Occupancy::Free);
  EXPECT_EQ(after.classify({0.99f, -0.39f, 0.45f}), ss::Occupancy::Free);
  // Outside the region nothing is copied.
  ASSERT_EQ(before.classify({0.01f, 0.11f, 0.25f}), ss::Occupancy::Free);  // target (0.89, -0.39, 0.45)
  const Eigen::AlignedBox3d smaller(Eigen::Vector3d(0.5, -0.9, 0.0), Eigen::Vector3d(0.95, 0.1, 1.0));
  const ss::OccupancyMap cut(ss::resampleOccupancy(*source, source_to_target, smaller));
  EXPECT_EQ(cut.classify({0.89f, -0.39f, 0.45f}), ss::Occupancy::Free);
  EXPECT_EQ(cut.classify({0.99f, -0.39f, 0.45f}), ss::Occupancy::Unknown);  // free in the source, outside
}

TEST(OctomapConversion, ResamplingRefusesEmptyOrHugeRegions) {
  octomap::OcTree source(0.01);
  fillScene(source);
  EXPECT_THROW(ss::resampleOccupancy(source, Eigen::Isometry3d::Identity(), Eigen::AlignedBox3d()), ss::InputError);
  const Eigen::AlignedBox3d ten_metres(Eigen::Vector3d::Constant(-5), Eigen::Vector3d::Constant(5));
  EXPECT_THROW(ss::resampleOccupancy(source, Eigen::Isometry3d::Identity(), ten_metres, 1000000), ss::InputError);
}

namespace {

std::string conversionError(const ss::OctomapMessage& message) {
  try {
    ss::occupancyFromMessage(message);
  } catch (const ss::InputError& error) {
    return error.what();
  }
  return "(accepted)";
}

// A chain of inner nodes, each one's first child the next, ending in an occupied leaf:
// `inner_levels` inner nodes put the leaf at depth `inner_levels`.
std::vector<int8_t> binaryChain(int inner_levels) {
  std::vector<int8_t> data;
  for (int level = 0; level + 1 < inner_levels; ++level) data.insert(data.end(), {0x03, 0x00});  // child 0 inner
  data.insert(data.end(), {0x02, 0x00});  // child 0 an occupied leaf
  return data;
}

}  // namespace

// Found by fuzzing (test/fuzz/corpus/octomap_message/crash_deep_binary_tree): message data went
// straight to OctoMap's recursive readers, which built trees deeper than OctoMap's 16 levels from
// a few bytes (a silently broken map: its leaf iterator and node count disagreed) and accepted a
// resolution of 3e205 m. Message data now goes through the same checked reader as .bt/.ot files.
TEST(OctomapConversion, MalformedTreeDataIsAClearError) {
  const std::string found =
      readFile(std::string(SOURCE_DIR) + "/test/fuzz/corpus/octomap_message/crash_deep_binary_tree");
  ASSERT_GT(found.size(), 10u);
  ss::OctomapMessage message;
  message.binary = (found[0] & 1) != 0;
  message.id = "ColorOcTree";  // index 1 of the fuzz target's ids
  std::memcpy(&message.resolution, found.data() + 2, sizeof(double));
  message.data.assign(found.begin() + 10, found.end());
  EXPECT_NE(conversionError(message).find("resolution"), std::string::npos) << conversionError(message);
  message.resolution = 0.05;
  EXPECT_NE(conversionError(message).find("corrupt OctoMap data"), std::string::npos) << conversionError(message);

  // OctoMap keys have 16 levels: a leaf at depth 16 is fine, one level more is not.
  message = ss::OctomapMessage();
  message.binary = true;
  message.id = "OcTree";
  message.resolution = 0.05;
  message.data = binaryChain(16);
  const auto tree = ss::occupancyFromMessage(message);
  EXPECT_EQ(tree->size(), 17u);
  EXPECT_EQ(tree->getNumLeafNodes(), 1u);
  // Child 0 at every level: the voxel with key 0, the map's lowest corner (-32768 * 0.05 m).
  EXPECT_EQ(ss::OccupancyMap(tree).classify({-1638.375f, -1638.375f, -1638.375f}), ss::Occupancy::Occupied);
  EXPECT_EQ(ss::OccupancyMap(tree).classify({-1638.325f, -1638.375f, -1638.375f}), ss::Occupancy::Unknown);
  message.data = binaryChain(17);
  EXPECT_NE(conversionError(message).find("deeper than 16 levels"), std::string::npos) << conversionError(message);

  // Full data: every child bit set, forever; a colour tree cut inside a node; a resolution no
  // map has.
  message.binary = false;
  message.data.assign(4000, static_cast<int8_t>(0xff));
  EXPECT_NE(conversionError(message).find("corrupt OctoMap data"), std::string::npos) << conversionError(message);
  octomap::ColorOcTree color(0.02);
  fillScene(color);
  message = ss::fullMessageFromTree(color);
  message.data.resize(message.data.size() - 3);
  EXPECT_NE(conversionError(message).find("corrupt OctoMap data"), std::string::npos) << conversionError(message);
  message = ss::fullMessageFromTree(color);
  message.resolution = std::numeric_limits<double>::infinity();
  EXPECT_NE(conversionError(message).find("resolution"), std::string::npos) << conversionError(message);
}
