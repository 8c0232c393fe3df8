// rostest: the node equals the core on the real KinectFusion scene. The scene is published as
// a robot sends it (cloud + binary octomap_msgs/Octomap, then also the table plane as
// pcl_msgs/ModelCoefficients in another frame), and the node's objects must be the very
// segments makeSegmenter(...)->segment(scene) finds on the same scene - without the plane and
// with it. Skipped when ../shared/data/real/kinfu_tabletop is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <set>

#include <boost/filesystem.hpp>
#include <pcl_msgs/ModelCoefficients.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include "ros_test_support.h"
#include "symmetry_segmentation/SegmentCloud.h"
#include "symmetry_segmentation/ros/cloud_conversion.h"
#include "symmetry_segmentation/ros/table_plane.h"
#include "symmetry_segmentation/scene_io.h"
#include "symmetry_segmentation/segmenter.h"

namespace ss = symmetry_segmentation;
using Response = ss::SegmentCloud::Response;

namespace {

/// The ~scene parameter, or ../shared/data/real/kinfu_tabletop.
std::string sceneDirectory() {
  std::string scene;
  ros::NodeHandle("~").getParam("scene", scene);
  return scene.empty() ? std::string(SHARED_DATA_DIR) + "/real/kinfu_tabletop" : scene;
}

using SegmentSet = std::multiset<std::vector<int>>;

SegmentSet segmentsOf(const ss::SegmentationResult& result) {
  SegmentSet segments;
  for (const auto& segment : result.segments) {
    std::vector<int> indices = segment.indices;
    std::sort(indices.begin(), indices.end());
    segments.insert(indices);
  }
  return segments;
}

SegmentSet segmentsOf(const ss::SegmentedObjectArray& objects) {
  SegmentSet segments;
  for (const auto& object : objects.objects) {
    std::vector<int> indices(object.indices.begin(), object.indices.end());
    std::sort(indices.begin(), indices.end());
    segments.insert(indices);
  }
  return segments;
}

/// ~segment on the latest cloud, retried while the node has no map yet (NO_OCCUPANCY).
ss::SegmentCloud segmentLatest() {
  ss::SegmentCloud srv;
  srv.request.timeout = 10.0;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(30);
  while (true) {
    EXPECT_TRUE(ros::service::waitForService("segmentation/segment", ros::Duration(30)));
    EXPECT_TRUE(ros::service::call("segmentation/segment", srv));
    if (srv.response.status != Response::NO_OCCUPANCY || ros::WallTime::now() > deadline) return srv;
    ros::WallDuration(0.5).sleep();
  }
}

}  // namespace

TEST(SegmentationKinfu, NodeEqualsCoreWithAndWithoutTheTablePlane) {
  const std::string directory = sceneDirectory();
  if (!boost::filesystem::exists(directory + "/cloud.ply")) GTEST_SKIP() << directory << " is absent";
  std::string config_file;
  ASSERT_TRUE(ros::NodeHandle("~").getParam("config_file", config_file));
  const ss::SegmentationConfig config = ss::loadConfigFile(config_file);
  const ss::Scene file_scene = ss::loadScene(directory);
  ASSERT_TRUE(file_scene.occupancy);
  ASSERT_TRUE(file_scene.table_plane);

  // What the node is sent: the cloud as a PointCloud2 and the map as octomap_server's binary map.
  ros::NodeHandle nh;
  const sensor_msgs::PointCloud2 cloud = ros_test::cloudMessage(*file_scene.cloud, "map", ros::Time(5000, 0));
  const ss::OctomapMessage map = ros_test::octomapMessage(*file_scene.occupancy, "map");
  auto cloud_pub = nh.advertise<sensor_msgs::PointCloud2>("segmentation/input", 1, true);
  auto map_pub = nh.advertise<ss::OctomapMessage>("segmentation/octomap", 1, true);
  map_pub.publish(map);
  cloud_pub.publish(cloud);
  ASSERT_TRUE(ros_test::spinUntil([&] { return cloud_pub.getNumSubscribers() > 0 && map_pub.getNumSubscribers() > 0; }, 30));

  // The same scene for the core: the cloud and map as the node reads them back, no origin (the
  // cloud is in the processing frame and carries none), and the table estimated.
  ss::Scene scene = ss::sceneFromCloudMessage(cloud);
  scene.occupancy = ss::occupancyFromMessage(map);

  const auto without = segmentLatest();
  ASSERT_EQ(without.response.status, Response::SUCCESS) << without.response.message;
  EXPECT_NE(without.response.message.find("table plane estimated"), std::string::npos) << without.response.message;
  const SegmentSet core_without = segmentsOf(ss::makeSegmenter("symmetry", config)->segment(scene));
  EXPECT_EQ(segmentsOf(without.response.objects), core_without);
  std::cout << "kinfu without the table plane: node " << without.response.objects.objects.size() << " objects, core "
            << core_without.size() << std::endl;

  // The table plane, as a plane detector would publish it: in its own frame ("table", a turned
  // and shifted static frame), latched. The node moves it into "map" through tf.
  Eigen::Isometry3d table_in_map = Eigen::Isometry3d::Identity();
  table_in_map.rotate(Eigen::AngleAxisd(0.6, Eigen::Vector3d(0.2, -1.0, 0.4).normalized()));
  table_in_map.pretranslate(Eigen::Vector3d(0.4, -0.3, 0.9));
  tf2_ros::StaticTransformBroadcaster broadcaster;
  geometry_msgs::TransformStamped transform;
  transform.header.stamp = ros::Time::now();
  transform.header.frame_id = "map";
  transform.child_frame_id = "table";
  transform.transform.translation.x = table_in_map.translation().x();
  transform.transform.translation.y = table_in_map.translation().y();
  transform.transform.translation.z = table_in_map.translation().z();
  const Eigen::Quaterniond rotation(table_in_map.rotation());
  transform.transform.rotation.x = rotation.x();
  transform.transform.rotation.y = rotation.y();
  transform.transform.rotation.z = rotation.z();
  transform.transform.rotation.w = rotation.w();
  broadcaster.sendTransform(transform);
  const Eigen::Vector4d in_table =
      ss::transformPlane(file_scene.table_plane->cast<double>(), table_in_map.inverse());
  pcl_msgs::ModelCoefficients plane;
  plane.header.frame_id = "table";
  plane.header.stamp = ros::Time(0);  // the cloud's stamp
  for (int i = 0; i < 4; ++i) plane.values.push_back(static_cast<float>(in_table[i]));
  auto plane_pub = nh.advertise<pcl_msgs::ModelCoefficients>("segmentation/table_plane", 1, true);
  plane_pub.publish(plane);
  ASSERT_TRUE(ros_test::spinUntil([&] { return plane_pub.getNumSubscribers() > 0; }, 30));
  ros::WallDuration(1.0).sleep();  // the latched plane reaches the node

  const auto with = segmentLatest();
  ASSERT_EQ(with.response.status, Response::SUCCESS) << with.response.message;
  EXPECT_NE(with.response.message.find("table plane from ~table_plane (topic)"), std::string::npos)
      << with.response.message;
  scene.table_plane = file_scene.table_plane;  // what segment_scene reads from table_plane.txt
  const SegmentSet core_with = segmentsOf(ss::makeSegmenter("symmetry", config)->segment(scene));
  EXPECT_EQ(segmentsOf(with.response.objects), core_with);
  // The plane is used, not only named: on this scene it changes the segments (a bear found with it).
  EXPECT_NE(core_with, core_without) << "the known plane changes the segments on this scene";
  // And what segment_scene finds in the scene directory (the .bt map with its log-odds instead
  // of the binary message): the same here.
  EXPECT_EQ(segmentsOf(with.response.objects), segmentsOf(ss::makeSegmenter("symmetry", config)->segment(file_scene)));
  std::cout << "kinfu with the table plane: node " << with.response.objects.objects.size() << " objects, core "
            << core_with.size() << std::endl;
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "segmentation_kinfu_test");
  ros::NodeHandle keep_node_alive;
  return RUN_ALL_TESTS();
}
