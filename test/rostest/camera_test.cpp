// rostest: one RGB-D camera through launch/camera.launch. Organized frames (no normals, no map,
// no sensor frame) are published at 30 Hz, as a camera driver does - a generated Kinect frame,
// and real OSD frames as scene_to_bag writes them when ../shared is there: objects come out, no
// backlog builds up (the node works on the newest frame, at most one waits), the labelled cloud
// and the label image keep the camera's layout (the generated frame's label image also holds
// its objects), and the rate the node keeps is printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include <pcl/common/io.h>
#include <pcl/point_types.h>
#include <pcl_conversions/pcl_conversions.h>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>

#include "symmetry_segmentation/SegmentedObjectArray.h"
#include "symmetry_segmentation/synthetic/scene_generator.h"

namespace ss = symmetry_segmentation;

namespace {

constexpr double kCameraRate = 30.0;
constexpr double kStreamSeconds = 8.0;
constexpr double kMaxStreamSeconds = 60.0;

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

/// What the node sent back while frames streamed in.
struct Stream {
  std::size_t sent = 0;
  std::vector<Result> results;
  sensor_msgs::Image::ConstPtr label_image;
  sensor_msgs::PointCloud2::ConstPtr labelled_cloud;
  double median_interval = 0.0;
  std::vector<double> latencies;
};

/// Publishes `frames` in turn at kCameraRate for kStreamSeconds (longer until three results
/// are back, at most kMaxStreamSeconds), each with a fresh stamp, and
/// collects the node's answers; prints the rate it kept.
Stream streamFrames(std::vector<sensor_msgs::PointCloud2> frames, const char* what) {
  ros::NodeHandle nh;
  Stream stream;
  std::mutex mutex;
  ros::Subscriber objects = nh.subscribe<ss::SegmentedObjectArray>(
      "/segmentation/objects", 10, [&](const ss::SegmentedObjectArray::ConstPtr& message) {
        std::lock_guard<std::mutex> lock(mutex);
        stream.results.push_back({message->header.stamp, ros::WallTime::now(), message->objects.size()});
      });
  ros::Subscriber images = nh.subscribe<sensor_msgs::Image>(
      "/segmentation/label_image", 1, [&](const sensor_msgs::Image::ConstPtr& message) {
        std::lock_guard<std::mutex> lock(mutex);
        stream.label_image = message;
      });
  ros::Subscriber clouds = nh.subscribe<sensor_msgs::PointCloud2>(
      "/segmentation/segmented_cloud", 1, [&](const sensor_msgs::PointCloud2::ConstPtr& message) {
        std::lock_guard<std::mutex> lock(mutex);
        stream.labelled_cloud = message;
      });
  ros::Publisher camera = nh.advertise<sensor_msgs::PointCloud2>("/camera/depth_registered/points", 1);
  ros::AsyncSpinner spinner(1);
  spinner.start();
  // Lazy: the node subscribes to the camera once ~objects has a subscriber.
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(60.0);
  while (camera.getNumSubscribers() == 0 && ros::WallTime::now() < deadline) ros::WallDuration(0.05).sleep();
  if (camera.getNumSubscribers() == 0 || frames.empty()) {
    spinner.stop();  // no callback writes to `stream` after this
    ADD_FAILURE() << "the node never subscribed to the camera, or no frames";
    return stream;
  }
  ros::WallRate rate(kCameraRate);
  const ros::WallTime start = ros::WallTime::now();
  // At least kStreamSeconds; longer (up to kMaxStreamSeconds) until three results are back: on a
  // loaded machine (a CI run's other jobs) the node's first frames take longer, and how long is a
  // benchmark's business - a backlog is judged from the latencies below.
  const auto streaming = [&] {
    const ros::WallDuration elapsed = ros::WallTime::now() - start;
    if (elapsed < ros::WallDuration(kStreamSeconds)) return true;
    std::lock_guard<std::mutex> lock(mutex);
    return stream.results.size() < 3 && elapsed < ros::WallDuration(kMaxStreamSeconds);
  };
  while (streaming()) {
    sensor_msgs::PointCloud2& frame = frames[stream.sent % frames.size()];
    frame.header.stamp = ros::Time::now();
    frame.header.seq = static_cast<uint32_t>(stream.sent++);
    camera.publish(frame);
    rate.sleep();
  }
  ros::WallDuration(3.0).sleep();  // the frame in progress finishes
  spinner.stop();

  std::lock_guard<std::mutex> lock(mutex);
  if (stream.results.size() < 3) return stream;
  std::vector<double> intervals;
  for (std::size_t i = 0; i < stream.results.size(); ++i) {
    stream.latencies.push_back(stream.results[i].received.toSec() - stream.results[i].cloud_stamp.toSec());
    if (i > 0) intervals.push_back((stream.results[i].received - stream.results[i - 1].received).toSec());
  }
  std::nth_element(intervals.begin(), intervals.begin() + intervals.size() / 2, intervals.end());
  stream.median_interval = intervals[intervals.size() / 2];
  const double kept_rate = (stream.results.size() - 1) /
                           (stream.results.back().received - stream.results.front().received).toSec();
  std::printf("%s at %.0f Hz: %zu frames sent, %zu segmented, %.2f Hz kept (median %.0f ms apart), "
              "latency first %.0f ms, last %.0f ms, max %.0f ms\n",
              what, kCameraRate, stream.sent, stream.results.size(), kept_rate, 1000.0 * stream.median_interval,
              1000.0 * stream.latencies.front(), 1000.0 * stream.latencies.back(),
              1000.0 * *std::max_element(stream.latencies.begin(), stream.latencies.end()));
  return stream;
}

/// Each result is of a frame at most one segmentation old: a queue of 30 Hz frames would put the
/// last result seconds behind. The labelled cloud and the label image keep the camera's layout.
void expectNoBacklogAndCameraLayout(const Stream& stream, const std::string& frame_id) {
  // A backlog grows: the latency of the middle result and of the last one. A single frame slowed
  // by the machine (another process, 2.07 s against 1.70 once in CI) is no backlog.
  const double allowed = 2.5 * stream.median_interval + 0.5;
  ASSERT_FALSE(stream.latencies.empty());
  std::vector<double> sorted = stream.latencies;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  EXPECT_LT(sorted[sorted.size() / 2], allowed) << "median latency";
  EXPECT_LT(stream.latencies.back(), allowed) << "last result's latency";
  ASSERT_TRUE(stream.labelled_cloud);
  EXPECT_EQ(stream.labelled_cloud->width, 640u);
  EXPECT_EQ(stream.labelled_cloud->height, 480u);
  ASSERT_TRUE(stream.label_image);
  EXPECT_EQ(stream.label_image->encoding, "mono16");
  EXPECT_EQ(stream.label_image->width, 640u);
  EXPECT_EQ(stream.label_image->height, 480u);
  EXPECT_EQ(stream.label_image->header.frame_id, frame_id);
}

std::set<int> labelsIn(const sensor_msgs::Image& image) {
  std::set<int> labels;
  for (std::size_t i = 0; i + 1 < image.data.size(); i += 2) labels.insert(image.data[i] | (image.data[i + 1] << 8));
  return labels;
}

/// A directory of its own under /tmp, removed with everything in it when this goes.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    char pattern[] = "/tmp/symseg_camera_test_XXXXXX";
    if (mkdtemp(pattern)) path_ = pattern;
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    if (!path_.empty()) std::filesystem::remove_all(path_, ignored);
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// The camera cloud of the bag scene_to_bag writes for `pcd`, run as a user runs it (rosrun, no
/// terminal input); "" or what went wrong.
std::string osdFrameThroughSceneToBag(const std::string& pcd, sensor_msgs::PointCloud2& frame) {
  if (pcd.find('\'') != std::string::npos) return "a quote in the path " + pcd;
  const TemporaryDirectory directory;
  if (directory.path().empty()) return "no temporary directory";
  const std::string bag_path = directory.path() + "/frame.bag";
  const std::string command = "rosrun symmetry_segmentation scene_to_bag '" + pcd + "' --output '" + bag_path +
                              "' --clouds 1 --frame camera_rgb_optical_frame"
                              " --cloud-topic /camera/depth_registered/points < /dev/null > /dev/null";
  const int status = std::system(command.c_str());
  if (status != 0) return "scene_to_bag exited with status " + std::to_string(status);
  try {
    rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
    for (const rosbag::MessageInstance& message :
         rosbag::View(bag, rosbag::TopicQuery("/camera/depth_registered/points"))) {
      if (const auto cloud = message.instantiate<sensor_msgs::PointCloud2>()) {
        frame = *cloud;
        return "";
      }
    }
  } catch (const std::exception& error) {
    return std::string("reading the bag: ") + error.what();
  }
  return "no cloud in the bag";
}

}  // namespace

TEST(OneCamera, ThirtyHertzFramesGiveObjectsWithoutABacklog) {
  const Stream stream = streamFrames({cameraFrame()}, "generated Kinect frame");
  ASSERT_GE(stream.results.size(), 3u) << "sent " << stream.sent << " frames";
  for (const Result& result : stream.results) EXPECT_GE(result.objects, 2u) << "an isolated scene of 5 objects";
  expectNoBacklogAndCameraLayout(stream, "camera_rgb_optical_frame");
  ASSERT_TRUE(stream.label_image);
  EXPECT_GE(labelsIn(*stream.label_image).size(), 3u) << "no object (0) and at least two objects";
}

// Real Kinect frames (OSD learn: boxes, stacked, cylindric), each a PCD that scene_to_bag wrote
// into a bag, streamed in turn at 30 Hz.
TEST(OneCamera, OsdFramesFromSceneToBagAtThirtyHertz) {
  const std::string directory = std::string(SHARED_DATA_DIR) + "/real/osd_learn/";
  std::vector<std::string> paths;
  for (const char* name : {"learn5", "learn20", "learn40"}) paths.push_back(directory + name + ".pcd");
  for (const std::string& pcd : paths) {
    if (!std::ifstream(pcd)) GTEST_SKIP() << pcd << " not there (../shared is optional)";
  }
  std::vector<sensor_msgs::PointCloud2> frames;
  for (const std::string& pcd : paths) {
    sensor_msgs::PointCloud2 frame;
    const std::string problem = osdFrameThroughSceneToBag(pcd, frame);
    ASSERT_EQ(problem, "") << pcd;
    ASSERT_EQ(frame.width, 640u);
    ASSERT_EQ(frame.height, 480u);
    frames.push_back(frame);
  }
  const Stream stream = streamFrames(frames, "OSD frames");
  ASSERT_GE(stream.results.size(), 3u) << "sent " << stream.sent << " frames";
  // Each frame holds objects on the table (2, 2 and 3); how many are found is the quality
  // figures' business, that some are is this test's.
  for (const Result& result : stream.results) EXPECT_GE(result.objects, 1u);
  expectNoBacklogAndCameraLayout(stream, "camera_rgb_optical_frame");
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "segmentation_camera_test");
  ros::NodeHandle keep_node_alive;
  return RUN_ALL_TESTS();
}
