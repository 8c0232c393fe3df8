// rostest: one RGB-D camera through launch/camera.launch. A generated Kinect frame (organized,
// no normals, no map, no sensor frame) is published at 30 Hz, as a camera driver does: objects
// come out, no backlog builds up (the node works on the newest frame, at most one waits), the
// labelled cloud keeps the camera's layout and a label image lines up with it, and the rate the
// node keeps is printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <vector>

#include <pcl/common/io.h>
#include <pcl/point_types.h>
#include <pcl_conversions/pcl_conversions.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>

#include <set>

#include "symmetry_segmentation/SegmentedObjectArray.h"
#include "symmetry_segmentation/synthetic/scene_generator.h"

namespace ss = symmetry_segmentation;

namespace {

constexpr double kCameraRate = 30.0;
constexpr double kStreamSeconds = 8.0;

struct Result {
  ros::Time cloud_stamp;
  ros::WallTime received;
  std::size_t objects = 0;
};

sensor_msgs::PointCloud2 cameraFrame() {
  ss::synthetic::GeneratorOptions options;
  options.kind = ss::synthetic::SceneKind::Isolated;
  options.seed = 43;
  ss::synthetic::useDepthSensor(options, "kinect");
  const ss::Scene scene = ss::synthetic::generateScene(options);
  pcl::PointCloud<pcl::PointXYZRGB> frame;  // as a driver sends it: no normal fields
  pcl::copyPointCloud(*scene.cloud, frame);
  sensor_msgs::PointCloud2 message;
  pcl::toROSMsg(frame, message);
  message.header.frame_id = "camera_rgb_optical_frame";
  return message;
}

}  // namespace

TEST(OneCamera, ThirtyHertzFramesGiveObjectsWithoutABacklog) {
  ros::NodeHandle nh;
  sensor_msgs::PointCloud2 frame = cameraFrame();
  ASSERT_EQ(frame.height, 480u);
  std::mutex mutex;
  std::vector<Result> results;
  ros::Subscriber objects = nh.subscribe<ss::SegmentedObjectArray>(
      "/segmentation/objects", 10, [&](const ss::SegmentedObjectArray::ConstPtr& message) {
        std::lock_guard<std::mutex> lock(mutex);
        results.push_back({message->header.stamp, ros::WallTime::now(), message->objects.size()});
      });
  sensor_msgs::Image::ConstPtr label_image;
  sensor_msgs::PointCloud2::ConstPtr labelled_cloud;
  ros::Subscriber images = nh.subscribe<sensor_msgs::Image>(
      "/segmentation/label_image", 1, [&](const sensor_msgs::Image::ConstPtr& message) {
        std::lock_guard<std::mutex> lock(mutex);
        label_image = message;
      });
  ros::Subscriber clouds = nh.subscribe<sensor_msgs::PointCloud2>(
      "/segmentation/segmented_cloud", 1, [&](const sensor_msgs::PointCloud2::ConstPtr& message) {
        std::lock_guard<std::mutex> lock(mutex);
        labelled_cloud = message;
      });
  ros::Publisher camera = nh.advertise<sensor_msgs::PointCloud2>("/camera/depth_registered/points", 1);
  ros::AsyncSpinner spinner(1);
  spinner.start();
  // Lazy: the node subscribes to the camera once ~objects has a subscriber.
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(60.0);
  while (camera.getNumSubscribers() == 0 && ros::WallTime::now() < deadline) ros::WallDuration(0.05).sleep();
  ASSERT_GT(camera.getNumSubscribers(), 0u) << "the node never subscribed to the camera";

  ros::WallRate rate(kCameraRate);
  const ros::WallTime start = ros::WallTime::now();
  std::size_t sent = 0;
  while (ros::WallTime::now() - start < ros::WallDuration(kStreamSeconds)) {
    frame.header.stamp = ros::Time::now();
    frame.header.seq = static_cast<uint32_t>(sent++);
    camera.publish(frame);
    rate.sleep();
  }
  ros::WallDuration(3.0).sleep();  // the frame in progress finishes

  std::lock_guard<std::mutex> lock(mutex);
  ASSERT_GE(results.size(), 3u) << "sent " << sent << " frames";
  for (const Result& result : results) EXPECT_GE(result.objects, 2u) << "an isolated scene of 5 objects";
  std::vector<double> intervals, latencies;
  for (std::size_t i = 0; i < results.size(); ++i) {
    latencies.push_back((results[i].received.toSec() - results[i].cloud_stamp.toSec()));
    if (i > 0) intervals.push_back((results[i].received - results[i - 1].received).toSec());
  }
  std::vector<double> sorted = intervals;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median_interval = sorted[sorted.size() / 2];
  const double kept_rate = (results.size() - 1) / (results.back().received - results.front().received).toSec();
  std::printf("camera at %.0f Hz: %zu frames sent, %zu segmented, %.2f Hz kept (median %.0f ms apart), "
              "latency first %.0f ms, last %.0f ms, max %.0f ms\n",
              kCameraRate, sent, results.size(), kept_rate, 1000.0 * median_interval, 1000.0 * latencies.front(),
              1000.0 * latencies.back(), 1000.0 * *std::max_element(latencies.begin(), latencies.end()));
  // Each result is of a frame at most one segmentation old: a queue of 30 Hz frames would put
  // the last result seconds behind.
  const double allowed = 2.5 * median_interval + 0.5;
  for (double latency : latencies) EXPECT_LT(latency, allowed);

  ASSERT_TRUE(labelled_cloud);
  EXPECT_EQ(labelled_cloud->width, 640u);
  EXPECT_EQ(labelled_cloud->height, 480u);
  ASSERT_TRUE(label_image);
  EXPECT_EQ(label_image->encoding, "mono16");
  EXPECT_EQ(label_image->width, 640u);
  EXPECT_EQ(label_image->height, 480u);
  EXPECT_EQ(label_image->header.frame_id, "camera_rgb_optical_frame");
  std::set<int> labels;
  for (std::size_t i = 0; i + 1 < label_image->data.size(); i += 2) {
    labels.insert(label_image->data[i] | (label_image->data[i + 1] << 8));
  }
  EXPECT_GE(labels.size(), 3u) << "no object (0) and at least two objects";
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "segmentation_camera_test");
  ros::NodeHandle keep_node_alive;
  return RUN_ALL_TESTS();
}
