// rostest: a generated scene published as cloud + octomap_msgs/Octomap (and then the table plane)
// gives exactly the ~objects the core library finds on the same scene; the labelled cloud and
// the markers are published too; ~input is subscribed only while someone listens; a cloud in
// another frame goes through tf; stale clouds are dropped while busy; /diagnostics reports.
#include <gtest/gtest.h>

#include <algorithm>

#include <map>
#include <set>

#include <pcl/point_types.h>
#include <diagnostic_msgs/DiagnosticArray.h>
#include <pcl_msgs/ModelCoefficients.h>
#include <ros/master.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include "ros_test_support.h"
#include "symmetry_segmentation/SegmentedObjectArray.h"
#include "symmetry_segmentation/evaluation/segmentation_metric.h"
#include "symmetry_segmentation/ros/cloud_conversion.h"
#include "symmetry_segmentation/ros/octomap_conversion.h"
#include "symmetry_segmentation/segmenter.h"

namespace ss = symmetry_segmentation;

namespace {

ss::Metrics metricsOf(const ss::Scene& scene, const std::vector<std::vector<int>>& segments) {
  return ss::computeMetrics(ss::countMatches(ss::computeOverlap(scene.labels, segments), 0.5));
}

}  // namespace

// Nodes the master lists as subscribers of `topic`, other than this test node.
std::vector<std::string> otherSubscribers(const std::string& topic) {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  std::vector<std::string> nodes;
  if (!ros::master::execute("getSystemState", args, result, payload, true)) {
    ADD_FAILURE() << "getSystemState failed";
    return nodes;
  }
  XmlRpc::XmlRpcValue& subscribers = payload[1];
  for (int i = 0; i < subscribers.size(); ++i) {
    if (static_cast<std::string>(subscribers[i][0]) != topic) continue;
    for (int j = 0; j < subscribers[i][1].size(); ++j) {
      const std::string node = subscribers[i][1][j];
      if (node != ros::this_node::getName()) nodes.push_back(node);
    }
  }
  return nodes;
}

TEST(SegmentationTopics, InputIsSubscribedOnlyWhileSomeoneListens) {
  // Runs first: nobody has subscribed an output yet. The node (lazy, like pcl_ros nodelets)
  // must not even receive clouds then, so it cannot segment them.
  ros::NodeHandle nh;
  // The reconfigure service is the last thing the nodelet sets up.
  ASSERT_TRUE(ros::service::waitForService("segmentation/set_parameters", ros::Duration(30)));
  auto cloud_pub = nh.advertise<sensor_msgs::PointCloud2>("segmentation/input", 1);
  auto map_pub = nh.advertise<ss::OctomapMessage>("segmentation/octomap", 1, true);
  const ss::Scene scene = ros_test::clutterScene(1);
  map_pub.publish(ros_test::octomapMessage(*scene.occupancy, "map"));
  const ros::Time unheard(500, 0);
  cloud_pub.publish(ros_test::cloudMessage(*scene.cloud, "map", unheard));
  // A negative check, nothing timed: it only gets stronger with a longer wait.
  ros_test::spinUntil([] { return false; }, 1.0);
  EXPECT_EQ(cloud_pub.getNumSubscribers(), 0u);
  EXPECT_TRUE(otherSubscribers("/segmentation/input").empty()) << otherSubscribers("/segmentation/input").at(0);
  EXPECT_FALSE(otherSubscribers("/segmentation/octomap").empty()) << "the map is always cached";

  // Someone subscribes to the markers only: the node subscribes ~input and segments.
  visualization_msgs::MarkerArray::ConstPtr markers;
  const ros::Time heard(600, 0);
  auto markers_sub = nh.subscribe<visualization_msgs::MarkerArray>(
      "segmentation/symmetry_markers", 1, [&](const visualization_msgs::MarkerArray::ConstPtr& m) {
        if (!m->markers.empty() && m->markers.front().header.stamp == heard) markers = m;
      });
  ASSERT_TRUE(ros_test::spinUntil([&] { return cloud_pub.getNumSubscribers() > 0; }, 30))
      << "~input not subscribed although ~symmetry_markers has a subscriber";
  EXPECT_FALSE(otherSubscribers("/segmentation/input").empty());
  cloud_pub.publish(ros_test::cloudMessage(*scene.cloud, "map", heard));
  ASSERT_TRUE(ros_test::spinUntil([&] { return markers != nullptr; }, 120)) << "no markers for the published cloud";
  EXPECT_EQ(markers->markers.back().ns, "object_list");
  EXPECT_TRUE(std::any_of(markers->markers.begin(), markers->markers.end(),
                          [](const visualization_msgs::Marker& m) { return m.ns == "planes"; }))
      << "no object found";

  // The last output subscriber leaves: ~input is unsubscribed again.
  markers_sub.shutdown();
  ASSERT_TRUE(ros_test::spinUntil([&] { return cloud_pub.getNumSubscribers() == 0; }, 30))
      << "~input still subscribed without any output subscriber";
  EXPECT_TRUE(otherSubscribers("/segmentation/input").empty());
}

TEST(SegmentationTopics, GeneratedSceneIsSegmentedLikeTheCoreDoes) {
  ros::NodeHandle nh;
  std::string config_file;
  ASSERT_TRUE(ros::NodeHandle("~").getParam("config_file", config_file));
  const ss::Scene scene = ros_test::clutterScene(1);
  ASSERT_TRUE(scene.occupancy);
  ASSERT_TRUE(scene.table_plane);
  ASSERT_FALSE(scene.labels.empty());

  ss::SegmentedObjectArray::ConstPtr objects;
  sensor_msgs::PointCloud2::ConstPtr labelled;
  visualization_msgs::MarkerArray::ConstPtr markers;
  ros::Time stamp(1000, 0);
  tf2_ros::Buffer tf_buffer;  // listening before the cloud goes out: /tf is not latched
  tf2_ros::TransformListener tf_listener(tf_buffer);
  auto objects_sub = nh.subscribe<ss::SegmentedObjectArray>(
      "segmentation/objects", 1, [&](const ss::SegmentedObjectArray::ConstPtr& m) { if (m->header.stamp == stamp) objects = m; });
  auto labelled_sub = nh.subscribe<sensor_msgs::PointCloud2>(
      "segmentation/segmented_cloud", 1, [&](const sensor_msgs::PointCloud2::ConstPtr& m) { if (m->header.stamp == stamp) labelled = m; });
  auto markers_sub = nh.subscribe<visualization_msgs::MarkerArray>(
      "segmentation/symmetry_markers", 1, [&](const visualization_msgs::MarkerArray::ConstPtr& m) {
        if (m->markers.front().header.stamp == stamp) markers = m;
      });
  auto cloud_pub = nh.advertise<sensor_msgs::PointCloud2>("segmentation/input", 1);
  auto map_pub = nh.advertise<ss::OctomapMessage>("segmentation/octomap", 1, true);  // latched, like octomap_server
  auto plane_pub = nh.advertise<pcl_msgs::ModelCoefficients>("segmentation/table_plane", 1, true);
  ASSERT_TRUE(ros_test::spinUntil([&] {
    return cloud_pub.getNumSubscribers() > 0 && map_pub.getNumSubscribers() > 0 && plane_pub.getNumSubscribers() > 0;
  }, 30));
  ASSERT_TRUE(ros_test::spinUntil([&] { return objects_sub.getNumPublishers() > 0; }, 30));
  const ss::OctomapMessage map = ros_test::octomapMessage(*scene.occupancy, "map");
  map_pub.publish(map);
  ros::WallDuration(0.5).sleep();  // the map is cached before the cloud arrives
  const sensor_msgs::PointCloud2 cloud = ros_test::cloudMessage(*scene.cloud, "map", stamp);
  cloud_pub.publish(cloud);
  ASSERT_TRUE(ros_test::spinUntil([&] { return objects && labelled && markers && markers->markers.size() > 1; }, 120))
      << "no outputs for the published cloud";

  // The core on the same scene, as the node received it: the cloud and the binary map read
  // back, no sensor origin (the cloud is in the processing frame), the table estimated. The
  // glue loses nothing: the very same segments.
  const ss::SegmentationConfig config = ss::loadConfigFile(config_file);
  ss::Scene received = ss::sceneFromCloudMessage(cloud);
  received.occupancy = ss::occupancyFromMessage(map);
  const auto same_input = ss::makeSegmenter("symmetry", config)->segment(received);
  ASSERT_EQ(objects->objects.size(), same_input.segments.size());
  std::vector<std::vector<int>> node_segments;
  for (const auto& object : objects->objects) node_segments.emplace_back(object.indices.begin(), object.indices.end());
  for (std::size_t i = 0; i < same_input.segments.size(); ++i) {
    EXPECT_EQ(node_segments[i], same_input.segments[i].indices) << "segment " << i;
  }
  EXPECT_EQ(objects->header.frame_id, "map");
  EXPECT_GT(metricsOf(scene, node_segments).recall, 0.3) << "too few ground-truth objects found";
  for (const auto& object : objects->objects) {
    EXPECT_TRUE(object.has_symmetry_plane);
    EXPECT_EQ(object.cloud.width * object.cloud.height, object.indices.size());
    EXPECT_GT(object.bounding_box_size.x, 0.0);
  }

  // Labelled cloud: one label per object, in the processing frame.
  EXPECT_EQ(labelled->header.frame_id, "map");
  EXPECT_TRUE(ss::hasField(*labelled, "label"));
  pcl::PointCloud<pcl::PointXYZRGBL> labelled_points;
  pcl::fromROSMsg(*labelled, labelled_points);
  std::set<uint32_t> labels;
  for (const auto& p : labelled_points) labels.insert(p.label);
  EXPECT_EQ(labels.size(), objects->objects.size() + 1);  // + 0 for unsegmented points

  // Markers: DELETEALL first, then per object plane, arrow, its completion's added points (when
  // it added any), its box and text, the table's outline (the table is estimated here), the
  // object list last.
  EXPECT_EQ(markers->markers.front().action, visualization_msgs::Marker::DELETEALL);
  std::size_t per_object = 0;
  for (const auto& object : objects->objects) {
    EXPECT_TRUE(object.has_completion);
    per_object += 4 + (object.completion_points > 0 ? 1 : 0);
  }
  EXPECT_EQ(markers->markers.size(), 1 + per_object + 1 + 1);

  // ~publish_object_frames: a tf frame per object, at the cloud's stamp, at its symmetry frame.
  for (const auto& object : objects->objects) {
    const std::string child = "object_" + std::to_string(object.id);
    ASSERT_TRUE(ros_test::spinUntil([&] { return tf_buffer.canTransform("map", child, stamp); }, 10)) << child;
    const auto frame = tf_buffer.lookupTransform("map", child, stamp);
    EXPECT_NEAR(frame.transform.translation.x, object.symmetry_frame.position.x, 1e-6) << child;
    EXPECT_NEAR(frame.transform.rotation.w, object.symmetry_frame.orientation.w, 1e-6) << child;
  }
  ASSERT_GE(markers->markers.size(), 2u);
  EXPECT_EQ(markers->markers[markers->markers.size() - 2].ns, "support");
  EXPECT_EQ(markers->markers.back().ns, "object_list");
  EXPECT_EQ(markers->markers.back().text.rfind(std::to_string(objects->objects.size()) + " objects\n", 0), 0u)
      << markers->markers.back().text;

  // The table plane on ~table_plane (what segment_scene reads from table_plane.txt): the node
  // passes it on, and finds what the core finds with it.
  pcl_msgs::ModelCoefficients plane;
  plane.header.frame_id = "map";
  plane.values.assign(scene.table_plane->data(), scene.table_plane->data() + 4);
  plane_pub.publish(plane);
  ros::WallDuration(0.5).sleep();
  objects.reset();
  stamp = ros::Time(1001, 0);
  cloud_pub.publish(ros_test::cloudMessage(*scene.cloud, "map", stamp));
  ASSERT_TRUE(ros_test::spinUntil([&] { return objects != nullptr; }, 120)) << "no objects with the table plane";
  received.table_plane = scene.table_plane;
  const auto with_plane = ss::makeSegmenter("symmetry", config)->segment(received);
  ASSERT_EQ(objects->objects.size(), with_plane.segments.size());
  for (std::size_t i = 0; i < with_plane.segments.size(); ++i) {
    EXPECT_EQ(std::vector<int>(objects->objects[i].indices.begin(), objects->objects[i].indices.end()),
              with_plane.segments[i].indices)
        << "segment " << i;
  }
  // Withdrawn (no values): the following tests run without it.
  plane.values.clear();
  plane_pub.publish(plane);
  ros::WallDuration(0.5).sleep();
}

TEST(SegmentationTopics, CloudInAnotherFrameGoesThroughTf) {
  // The cloud arrives in a camera frame; the map (already cached) is in "map", so processing
  // happens in "map" once tf2 knows camera -> map: same segments, stamped with the cloud's stamp.
  ros::NodeHandle nh;
  const ss::Scene scene = ros_test::clutterScene(1);
  const Eigen::Vector3f origin = scene.sensor_origins.at(0);
  ss::SegmentedObjectArray::ConstPtr objects;
  const ros::Time stamp(3000, 0);
  auto objects_sub = nh.subscribe<ss::SegmentedObjectArray>(
      "segmentation/objects", 1, [&](const ss::SegmentedObjectArray::ConstPtr& m) { if (m->header.stamp == stamp) objects = m; });
  auto cloud_pub = nh.advertise<sensor_msgs::PointCloud2>("segmentation/input", 1);
  ASSERT_TRUE(ros_test::spinUntil([&] { return cloud_pub.getNumSubscribers() > 0 && objects_sub.getNumPublishers() > 0; }, 30));
  ss::Cloud in_camera = *scene.cloud;
  for (auto& p : in_camera) {
    p.x -= origin.x();
    p.y -= origin.y();
    p.z -= origin.z();
  }
  // First without the transform: dropped by the tf filter (a warning), nothing published.
  cloud_pub.publish(ros_test::cloudMessage(in_camera, "camera", stamp));
  EXPECT_FALSE(ros_test::spinUntil([&] { return objects != nullptr; }, 3.0)) << "segmented without a transform";

  tf2_ros::StaticTransformBroadcaster broadcaster;
  geometry_msgs::TransformStamped transform;
  transform.header.stamp = ros::Time(0);
  transform.header.frame_id = "map";
  transform.child_frame_id = "camera";
  transform.transform.translation.x = origin.x();
  transform.transform.translation.y = origin.y();
  transform.transform.translation.z = origin.z();
  transform.transform.rotation.w = 1.0;
  broadcaster.sendTransform(transform);
  ros::WallDuration(0.5).sleep();
  cloud_pub.publish(ros_test::cloudMessage(in_camera, "camera", stamp));
  ASSERT_TRUE(ros_test::spinUntil([&] { return objects != nullptr; }, 60)) << "no objects for the camera-frame cloud";
  EXPECT_EQ(objects->header.frame_id, "map");
  EXPECT_GE(objects->objects.size(), 3u);
  for (const auto& object : objects->objects) {
    EXPECT_GT(object.bounding_box_pose.position.z, -0.05) << "boxes are in the map frame, on the table";
  }
}

TEST(SegmentationTopics, StaleCloudsAreDroppedWhenBusy) {
  // Ten clouds at once: the node never queues them all; the newest one is always segmented.
  ros::NodeHandle nh;
  const ss::Scene scene = ros_test::clutterScene(1);
  std::vector<ros::Time> stamps;
  auto objects_sub = nh.subscribe<ss::SegmentedObjectArray>(
      "segmentation/objects", 10, [&](const ss::SegmentedObjectArray::ConstPtr& m) {
        if (m->header.stamp.sec >= 4000) stamps.push_back(m->header.stamp);
      });
  auto cloud_pub = nh.advertise<sensor_msgs::PointCloud2>("segmentation/input", 10);
  ASSERT_TRUE(ros_test::spinUntil([&] { return cloud_pub.getNumSubscribers() > 0 && objects_sub.getNumPublishers() > 0; }, 30));
  const sensor_msgs::PointCloud2 message = ros_test::cloudMessage(*scene.cloud, "map", ros::Time(0));
  for (int i = 0; i < 10; ++i) {
    auto copy = boost::make_shared<sensor_msgs::PointCloud2>(message);
    copy->header.stamp = ros::Time(4000 + i, 0);
    cloud_pub.publish(copy);
    ros::WallDuration(0.02).sleep();
  }
  ASSERT_TRUE(ros_test::spinUntil([&] { return !stamps.empty() && stamps.back() == ros::Time(4009, 0); }, 60))
      << "the newest cloud was not segmented";
  ros_test::spinUntil([] { return false; }, 2.0);  // anything still queued would arrive now
  EXPECT_LT(stamps.size(), 10u) << "every cloud was segmented: nothing was dropped";
  EXPECT_EQ(stamps.back(), ros::Time(4009, 0));
}

TEST(SegmentationTopics, DiagnosticsReportSegmentationsDurationAndDrops) {
  // After the tests above (several clouds segmented, some dropped while busy), /diagnostics
  // says so, as ROS drivers report.
  ros::NodeHandle nh;
  diagnostic_msgs::DiagnosticStatus status;
  auto sub = nh.subscribe<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10, [&](const diagnostic_msgs::DiagnosticArray::ConstPtr& m) {
    for (const auto& s : m->status) {
      if (s.name.find("segmentation") != std::string::npos) status = s;
    }
  });
  ASSERT_TRUE(ros_test::spinUntil([&] { return !status.values.empty(); }, 10)) << "nothing on /diagnostics";
  std::map<std::string, std::string> values;
  for (const auto& kv : status.values) values[kv.key] = kv.value;
  EXPECT_EQ(status.level, diagnostic_msgs::DiagnosticStatus::OK) << status.message;
  ASSERT_TRUE(values.count("segmented clouds"));
  EXPECT_GE(std::stoi(values["segmented clouds"]), 3);
  ASSERT_TRUE(values.count("dropped clouds"));
  EXPECT_GE(std::stoi(values["dropped clouds"]), 1) << "StaleCloudsAreDroppedWhenBusy dropped some";
  ASSERT_TRUE(values.count("last duration (ms)"));
  EXPECT_GT(std::stod(values["last duration (ms)"]), 0.0);
  EXPECT_EQ(values["last status"], "SUCCESS");
  EXPECT_TRUE(values.count("segmentation rate (Hz)"));
  EXPECT_EQ(values["mode"], "continuous");
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "segmentation_topics_test");
  ros::NodeHandle keep_node_alive;  // the node shuts down when its last handle goes
  return RUN_ALL_TESTS();
}
