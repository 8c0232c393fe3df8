// rostest: ~segment returns SUCCESS with objects, and each failure status on its own cause.
// The tests run in order: first without any input, then with a cloud, then with a map.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include <geometry_msgs/TransformStamped.h>
#include <dynamic_reconfigure/Reconfigure.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include "ros_test_support.h"
#include "symmetry_segmentation/SegmentCloud.h"

namespace ss = symmetry_segmentation;
using Response = ss::SegmentCloud::Response;

namespace {

const ss::Scene& scene() {
  static const ss::Scene generated = ros_test::clutterScene(2);
  return generated;
}

ss::SegmentCloud call(const ss::SegmentCloud::Request& request) {
  ss::SegmentCloud srv;
  srv.request = request;
  EXPECT_TRUE(ros::service::waitForService("segmentation/segment", ros::Duration(30)));
  EXPECT_TRUE(ros::service::call("segmentation/segment", srv)) << "the call itself failed (node died?)";
  return srv;
}

sensor_msgs::PointCloud2 cloudWith(const std::vector<Eigen::Vector3f>& points, const std::string& frame) {
  ss::Cloud cloud;
  for (const auto& p : points) {
    ss::PointT q;
    q.x = p.x();
    q.y = p.y();
    q.z = p.z();
    cloud.push_back(q);
  }
  return ros_test::cloudMessage(cloud, frame, ros::Time::now());
}

}  // namespace

TEST(SegmentService, NoCloudYet) {
  const auto srv = call({});
  EXPECT_EQ(srv.response.status, Response::NO_CLOUD) << srv.response.message;
  EXPECT_FALSE(srv.response.message.empty());
}

TEST(SegmentService, TimeoutWaitingForACloud) {
  ss::SegmentCloud::Request request;
  request.timeout = 0.3;
  const ros::WallTime start = ros::WallTime::now();
  const auto srv = call(request);
  EXPECT_EQ(srv.response.status, Response::TIMEOUT) << srv.response.message;
  EXPECT_GE((ros::WallTime::now() - start).toSec(), 0.3);
}

TEST(SegmentService, EmptyCloudIsInvalid) {
  ss::SegmentCloud::Request request;
  request.cloud = cloudWith({}, "map");
  ASSERT_FALSE(request.cloud.fields.empty());
  const auto srv = call(request);
  EXPECT_EQ(srv.response.status, Response::INVALID_INPUT) << srv.response.message;
  EXPECT_NE(srv.response.message.find("empty"), std::string::npos) << srv.response.message;
}

TEST(SegmentService, NanOnlyCloudIsInvalid) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  ss::SegmentCloud::Request request;
  request.cloud = cloudWith({{nan, nan, nan}, {nan, 0, 1}, {0, nan, 1}}, "map");
  const auto srv = call(request);
  EXPECT_EQ(srv.response.status, Response::INVALID_INPUT) << srv.response.message;
  EXPECT_NE(srv.response.message.find("finite"), std::string::npos) << srv.response.message;
}

TEST(SegmentService, InconsistentCloudsAreInvalidWithTheReason) {
  // Each broken the way a buggy driver breaks it; the message names what is wrong.
  ss::SegmentCloud::Request request;
  request.cloud = ros_test::cloudMessage(*scene().cloud, "map", ros::Time::now());
  request.cloud.row_step -= 1;  // rows no longer hold width points
  auto srv = call(request);
  EXPECT_EQ(srv.response.status, Response::INVALID_INPUT) << srv.response.message;
  EXPECT_NE(srv.response.message.find("row_step"), std::string::npos) << srv.response.message;

  request.cloud = ros_test::cloudMessage(*scene().cloud, "map", ros::Time::now());
  request.cloud.data.resize(request.cloud.data.size() / 2);
  srv = call(request);
  EXPECT_EQ(srv.response.status, Response::INVALID_INPUT) << srv.response.message;
  EXPECT_NE(srv.response.message.find("data holds"), std::string::npos) << srv.response.message;

  request.cloud = ros_test::cloudMessage(*scene().cloud, "map", ros::Time::now());
  for (auto& field : request.cloud.fields) {
    if (field.name == "z") field.datatype = sensor_msgs::PointField::FLOAT64;
  }
  srv = call(request);
  EXPECT_EQ(srv.response.status, Response::INVALID_INPUT) << srv.response.message;
  EXPECT_NE(srv.response.message.find("'z'"), std::string::npos) << srv.response.message;

  request.cloud = ros_test::cloudMessage(*scene().cloud, "", ros::Time::now());
  srv = call(request);
  EXPECT_EQ(srv.response.status, Response::INVALID_INPUT) << srv.response.message;
  EXPECT_NE(srv.response.message.find("frame_id"), std::string::npos) << srv.response.message;
}

TEST(SegmentService, NoOccupancyAndNoSensorFrame) {
  // In the fixed frame itself, so the cloud carries no viewpoint either.
  ss::SegmentCloud::Request request;
  request.cloud = ros_test::cloudMessage(*scene().cloud, "map", ros::Time::now());
  const auto srv = call(request);
  EXPECT_EQ(srv.response.status, Response::NO_OCCUPANCY) << srv.response.message;
}

TEST(SegmentService, MissingTransform) {
  ss::SegmentCloud::Request request;
  request.cloud = ros_test::cloudMessage(*scene().cloud, "frame_nobody_publishes", ros::Time::now());
  const auto srv = call(request);
  EXPECT_EQ(srv.response.status, Response::TRANSFORM_FAILED) << srv.response.message;
  EXPECT_NE(srv.response.message.find("frame_nobody_publishes"), std::string::npos) << srv.response.message;
}

TEST(SegmentService, RayCastFromTheCloudViewpoint) {
  // The cloud in a camera frame at the first sensor origin: the node transforms it into "map"
  // and ray-casts occupancy from the camera frame's origin.
  const Eigen::Vector3f origin = scene().sensor_origins.at(0);
  tf2_ros::StaticTransformBroadcaster broadcaster;
  geometry_msgs::TransformStamped transform;
  transform.header.stamp = ros::Time::now();
  transform.header.frame_id = "map";
  transform.child_frame_id = "camera";
  transform.transform.translation.x = origin.x();
  transform.transform.translation.y = origin.y();
  transform.transform.translation.z = origin.z();
  transform.transform.rotation.w = 1.0;
  broadcaster.sendTransform(transform);
  ss::Cloud in_camera = *scene().cloud;
  for (auto& p : in_camera) {
    p.x -= origin.x();
    p.y -= origin.y();
    p.z -= origin.z();
  }
  ss::SegmentCloud::Request request;
  request.cloud = ros_test::cloudMessage(in_camera, "camera", ros::Time(0));
  request.timeout = 2.0;
  const auto srv = call(request);
  ASSERT_EQ(srv.response.status, Response::SUCCESS) << srv.response.message;
  EXPECT_EQ(srv.response.objects.header.frame_id, "map");
  for (const auto& object : srv.response.objects.objects) {
    // Back in the map frame: the boxes sit on the table (z = 0), not around the camera.
    EXPECT_GT(object.bounding_box_pose.position.z, -0.05);
    EXPECT_LT(object.bounding_box_pose.position.z, 0.5);
  }
}

TEST(SegmentService, SuccessWithLatestCloudAndCachedMap) {
  ros::NodeHandle nh;
  auto cloud_pub = nh.advertise<sensor_msgs::PointCloud2>("segmentation/input", 1, true);
  auto map_pub = nh.advertise<ss::OctomapMessage>("segmentation/octomap", 1, true);
  ASSERT_TRUE(ros_test::spinUntil([&] { return cloud_pub.getNumSubscribers() > 0 && map_pub.getNumSubscribers() > 0; }, 30));
  map_pub.publish(ros_test::octomapMessage(*scene().occupancy, "map"));
  ros::WallDuration(0.5).sleep();
  cloud_pub.publish(ros_test::cloudMessage(*scene().cloud, "map", ros::Time(2000, 0)));
  ss::SegmentCloud::Request request;
  request.timeout = 5.0;
  const auto srv = call(request);
  ASSERT_EQ(srv.response.status, Response::SUCCESS) << srv.response.message;
  EXPECT_EQ(srv.response.objects.header.stamp, ros::Time(2000, 0));
  EXPECT_EQ(srv.response.objects.header.frame_id, "map");
  EXPECT_GE(srv.response.objects.objects.size(), 2u);
  ASSERT_FALSE(srv.response.timing_stages.empty());
  EXPECT_EQ(srv.response.timing_stages.back(), "total");
  EXPECT_EQ(srv.response.timing_stages.size(), srv.response.timing_ms.size());
  EXPECT_GT(srv.response.timing_ms.back(), 0.0);
  // The symmetry method completes every object: its points and the added ones, box and frame.
  for (const auto& object : srv.response.objects.objects) {
    ASSERT_TRUE(object.has_completion) << "object " << object.id;
    EXPECT_EQ(object.completed_cloud.width * object.completed_cloud.height,
              object.cloud.width * object.cloud.height + object.completion_points);
    EXPECT_GE(object.completed_box_size.z + 1e-6, object.bounding_box_size.z);
  }

  // A reply to print: the same objects without their clouds.
  ss::SegmentCloud::Request small_request;
  small_request.timeout = 5.0;
  small_request.without_clouds = true;
  const auto small = call(small_request);
  ASSERT_EQ(small.response.status, Response::SUCCESS) << small.response.message;
  ASSERT_EQ(small.response.objects.objects.size(), srv.response.objects.objects.size());
  for (std::size_t i = 0; i < small.response.objects.objects.size(); ++i) {
    const auto& object = small.response.objects.objects[i];
    EXPECT_TRUE(object.cloud.data.empty());
    EXPECT_TRUE(object.completed_cloud.data.empty());
    EXPECT_EQ(object.indices, srv.response.objects.objects[i].indices);
    EXPECT_EQ(object.completion_points, srv.response.objects.objects[i].completion_points);
  }

  // A region of interest around the first object keeps only objects inside it.
  const auto& first = srv.response.objects.objects.at(0);
  ss::SegmentCloud::Request roi_request;
  roi_request.timeout = 1.0;
  roi_request.use_roi = true;
  const auto& c = first.bounding_box_pose.position;
  const double r = 0.5 * std::max({first.bounding_box_size.x, first.bounding_box_size.y, first.bounding_box_size.z}) + 0.02;
  roi_request.roi_min.x = c.x - r;
  roi_request.roi_min.y = c.y - r;
  roi_request.roi_min.z = c.z - r;
  roi_request.roi_max.x = c.x + r;
  roi_request.roi_max.y = c.y + r;
  roi_request.roi_max.z = c.z + r;
  const auto roi_srv = call(roi_request);
  ASSERT_EQ(roi_srv.response.status, Response::SUCCESS) << roi_srv.response.message;
  for (const auto& object : roi_srv.response.objects.objects) {
    for (int index : object.indices) {
      const auto& p = scene().cloud->points.at(index);
      EXPECT_GE(p.x, c.x - r - 1e-4);
      EXPECT_LE(p.x, c.x + r + 1e-4);
    }
  }
}

TEST(SegmentService, LiveThresholdChangeTakesEffect) {
  // dynamic_reconfigure (the server of section symmetry.filter): s_occl 1.0 keeps no segment
  // (the score must exceed it); back to the configured value, objects return. Uses the latest
  // cloud and map of the previous test.
  auto set_s_occl = [](double value) {
    dynamic_reconfigure::Reconfigure reconfigure;
    dynamic_reconfigure::DoubleParameter parameter;
    parameter.name = "s_occl";
    parameter.value = value;
    reconfigure.request.config.doubles.push_back(parameter);
    EXPECT_TRUE(ros::service::waitForService("segmentation/symmetry/filter/set_parameters", ros::Duration(10)));
    EXPECT_TRUE(ros::service::call("segmentation/symmetry/filter/set_parameters", reconfigure));
    for (const auto& applied : reconfigure.response.config.doubles) {
      if (applied.name == "s_occl") return applied.value;
    }
    return -1.0;
  };
  EXPECT_DOUBLE_EQ(set_s_occl(1.0), 1.0);
  double stored = 0.0;
  EXPECT_TRUE(ros::param::get("segmentation/symmetry/filter/s_occl", stored));
  EXPECT_DOUBLE_EQ(stored, 1.0) << "the live name is the nested name";
  ss::SegmentCloud::Request request;
  request.timeout = 1.0;
  auto srv = call(request);
  ASSERT_EQ(srv.response.status, Response::SUCCESS) << srv.response.message;
  EXPECT_TRUE(srv.response.objects.objects.empty()) << srv.response.objects.objects.size() << " objects";
  EXPECT_DOUBLE_EQ(set_s_occl(0.99), 0.99);
  srv = call(request);
  ASSERT_EQ(srv.response.status, Response::SUCCESS) << srv.response.message;
  EXPECT_GE(srv.response.objects.objects.size(), 2u);
}

TEST(SegmentService, BadOctomapIsLoggedAndIgnored) {
  // A map of a tree type the node cannot use, and one with garbage data: both are rejected with
  // a logged error; the node keeps the last good map and keeps serving.
  ros::NodeHandle nh;
  auto map_pub = nh.advertise<ss::OctomapMessage>("segmentation/octomap", 2);
  ASSERT_TRUE(ros_test::spinUntil([&] { return map_pub.getNumSubscribers() > 0; }, 30));
  ss::OctomapMessage unsupported = ros_test::octomapMessage(*scene().occupancy, "map");
  unsupported.binary = false;
  unsupported.id = "OcTreeStamped";
  map_pub.publish(unsupported);
  ss::OctomapMessage garbage = ros_test::octomapMessage(*scene().occupancy, "map");
  garbage.id = "OcTree";  // binary, but the bytes are no tree
  garbage.data.assign(100, 7);
  map_pub.publish(garbage);
  ros::WallDuration(0.5).sleep();
  ss::SegmentCloud::Request request;
  request.timeout = 1.0;
  const auto srv = call(request);
  ASSERT_EQ(srv.response.status, Response::SUCCESS) << srv.response.message;
  EXPECT_GE(srv.response.objects.objects.size(), 2u);
}

TEST(SegmentService, OctomapInAnotherFrameIsTransformed) {
  // The same occupancy, once in "map" (the processing frame) and once expressed in "odom" (a
  // quarter turn and whole voxels away): with tf map -> odom, the node moves the map into "map"
  // and finds the same objects; before the transform exists, it says which frame is missing.
  ros::NodeHandle nh;
  auto map_pub = nh.advertise<ss::OctomapMessage>("segmentation/octomap", 1, true);
  ASSERT_TRUE(ros_test::spinUntil([&] { return map_pub.getNumSubscribers() > 0; }, 30));
  map_pub.publish(ros_test::octomapMessage(*scene().occupancy, "map"));
  ros::WallDuration(0.5).sleep();
  ss::SegmentCloud::Request request;
  request.cloud = ros_test::cloudMessage(*scene().cloud, "map", ros::Time(0));
  const auto in_map = call(request);
  ASSERT_EQ(in_map.response.status, Response::SUCCESS) << in_map.response.message;
  ASSERT_GE(in_map.response.objects.objects.size(), 2u);

  const double resolution = scene().occupancy->getResolution();
  Eigen::Isometry3d odom_in_map = Eigen::Isometry3d::Identity();  // p_map = odom_in_map * p_odom
  odom_in_map.rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  odom_in_map.pretranslate(resolution * Eigen::Vector3d(40, -20, 8));
  double min_x, min_y, min_z, max_x, max_y, max_z;
  scene().occupancy->getMetricMin(min_x, min_y, min_z);
  scene().occupancy->getMetricMax(max_x, max_y, max_z);
  Eigen::AlignedBox3d in_odom;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d p(corner & 1 ? max_x : min_x, corner & 2 ? max_y : min_y, corner & 4 ? max_z : min_z);
    in_odom.extend(odom_in_map.inverse() * p);
  }
  const auto odom_tree = ss::resampleOccupancy(*scene().occupancy, odom_in_map.inverse(), in_odom);
  map_pub.publish(ros_test::octomapMessage(*odom_tree, "odom"));
  ros::WallDuration(0.5).sleep();
  const auto no_tf = call(request);
  EXPECT_EQ(no_tf.response.status, Response::TRANSFORM_FAILED) << no_tf.response.message;
  EXPECT_NE(no_tf.response.message.find("'odom'"), std::string::npos) << no_tf.response.message;

  tf2_ros::StaticTransformBroadcaster broadcaster;
  geometry_msgs::TransformStamped transform;
  transform.header.stamp = ros::Time::now();
  transform.header.frame_id = "map";
  transform.child_frame_id = "odom";
  transform.transform.translation.x = odom_in_map.translation().x();
  transform.transform.translation.y = odom_in_map.translation().y();
  transform.transform.translation.z = odom_in_map.translation().z();
  const Eigen::Quaterniond rotation(odom_in_map.rotation());
  transform.transform.rotation.x = rotation.x();
  transform.transform.rotation.y = rotation.y();
  transform.transform.rotation.z = rotation.z();
  transform.transform.rotation.w = rotation.w();
  broadcaster.sendTransform(transform);
  request.timeout = 2.0;
  const auto moved = call(request);
  ASSERT_EQ(moved.response.status, Response::SUCCESS) << moved.response.message;
  EXPECT_EQ(moved.response.objects.header.frame_id, "map");
  ASSERT_EQ(moved.response.objects.objects.size(), in_map.response.objects.objects.size());
  for (std::size_t i = 0; i < moved.response.objects.objects.size(); ++i) {
    EXPECT_EQ(moved.response.objects.objects[i].indices, in_map.response.objects.objects[i].indices) << "object " << i;
  }
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "segmentation_service_test");
  ros::NodeHandle keep_node_alive;  // the node shuts down when its last handle goes
  return RUN_ALL_TESTS();
}
