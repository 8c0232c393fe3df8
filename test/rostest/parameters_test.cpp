// rostest: the algorithm parameters are read at start-up all at once and validated as one
// configuration (an invalid value or an unknown name rejects it, logged, and the defaults stay
// in force); a live parameter has one name, the nested one, before and after a live change; a
// live change that fails validation is rejected and dynamic_reconfigure shows the values in
// force; the ~table_plane parameter, given in another frame, is used. Each case loads the
// nodelet into a bare manager after setting its parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include <dynamic_reconfigure/Reconfigure.h>
#include <nodelet/NodeletLoad.h>
#include <nodelet/NodeletUnload.h>
#include <rosgraph_msgs/Log.h>

#include <geometry_msgs/TransformStamped.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include "ros_test_support.h"
#include "symmetry_segmentation/SegmentCloud.h"
#include "symmetry_segmentation/ros/cloud_conversion.h"
#include "symmetry_segmentation/ros/octomap_conversion.h"
#include "symmetry_segmentation/ros/table_plane.h"
#include "symmetry_segmentation/segmenter.h"

namespace ss = symmetry_segmentation;

namespace {

// Every /rosout message since the test started.
class LogWatch {
 public:
  LogWatch() {
    subscriber_ = ros::NodeHandle().subscribe<rosgraph_msgs::Log>("/rosout", 100, [this](const rosgraph_msgs::Log::ConstPtr& m) {
      std::lock_guard<std::mutex> lock(mutex_);
      lines_.push_back(m->msg);
    });
    // This process publishes on /rosout too: wait for the nodelet manager's connection as well,
    // or what the nodelet logs right after loading can go out before it and be lost.
    ros_test::spinUntil([this] { return subscriber_.getNumPublishers() >= 2; }, 10);
  }
  /// Waits up to `seconds` for a line containing every one of `parts`.
  bool saw(const std::vector<std::string>& parts, double seconds = 10.0) {
    return ros_test::spinUntil(
        [&] {
          std::lock_guard<std::mutex> lock(mutex_);
          for (const auto& line : lines_) {
            bool all = true;
            for (const auto& part : parts) all = all && line.find(part) != std::string::npos;
            if (all) return true;
          }
          return false;
        },
        seconds);
  }

 private:
  ros::Subscriber subscriber_;
  std::mutex mutex_;
  std::vector<std::string> lines_;
};

LogWatch& logs() {
  static LogWatch watch;
  return watch;
}

std::string manager() {
  std::string name;
  EXPECT_TRUE(ros::NodeHandle("~").getParam("manager", name));
  return name;
}

/// Loads SegmentationNodelet as `name` (parameters already set); true when it started.
bool load(const std::string& name) {
  logs();  // subscribed before the nodelet logs
  nodelet::NodeletLoad srv;
  srv.request.name = name;
  srv.request.type = "symmetry_segmentation/SegmentationNodelet";
  if (!ros::service::waitForService(manager() + "/load_nodelet", ros::Duration(30))) return false;
  return ros::service::call(manager() + "/load_nodelet", srv) && srv.response.success;
}

void unload(const std::string& name) {
  nodelet::NodeletUnload srv;
  srv.request.name = name;
  ros::service::call(manager() + "/unload_nodelet", srv);
}

double parameter(const std::string& name) {
  double value = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(ros::param::get(name, value)) << name << " is not set";
  return value;
}

/// Sets doubles through `server`'s set_parameters; returns what the server reports in force.
dynamic_reconfigure::Config reconfigure(const std::string& server, const std::vector<std::pair<std::string, double>>& values) {
  dynamic_reconfigure::Reconfigure srv;
  for (const auto& [name, value] : values) {
    dynamic_reconfigure::DoubleParameter parameter;
    parameter.name = name;
    parameter.value = value;
    srv.request.config.doubles.push_back(parameter);
  }
  EXPECT_TRUE(ros::service::waitForService(server + "/set_parameters", ros::Duration(10)));
  EXPECT_TRUE(ros::service::call(server + "/set_parameters", srv));
  return srv.response.config;
}

double valueIn(const dynamic_reconfigure::Config& config, const std::string& name) {
  for (const auto& parameter : config.doubles) {
    if (parameter.name == name) return parameter.value;
  }
  ADD_FAILURE() << name << " not in the reconfigure response";
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

TEST(SegmentationParameters, AnInvalidStartupValueRejectsTheWholeConfiguration) {
  // s_occl 1.5 is out of [0, 1]; s_smooth 0.05 is fine but part of the same configuration.
  ros::param::set("/invalid/symmetry/filter/s_occl", 1.5);
  ros::param::set("/invalid/symmetry/filter/s_smooth", 0.05);
  ros::param::set("/invalid/mode", "on_demand");
  ASSERT_TRUE(load("/invalid"));
  EXPECT_TRUE(logs().saw({"rejected the algorithm parameters in /invalid"}));
  EXPECT_TRUE(logs().saw({"s_occl", "1.5"})) << "the problem is named";
  // The live servers show (and store) the values in force: the defaults, both of them.
  EXPECT_NEAR(parameter("/invalid/symmetry/filter/s_occl"), 0.99, 1e-6);
  EXPECT_NEAR(parameter("/invalid/symmetry/filter/s_smooth"), 0.02, 1e-6);
  unload("/invalid");
}

TEST(SegmentationParameters, AnUnknownNameIsAnErrorNamingIt) {
  ros::param::set("/unknown/symmetry/filtr/s_occl", 0.97);  // a typo of a section
  ros::param::set("/unknown/sesnor_frame", "camera");       // a typo of an interface parameter
  ros::param::set("/unknown/symmetry/filter/s_smooth", 0.05);
  ros::param::set("/unknown/mode", "on_demand");
  ASSERT_TRUE(load("/unknown"));
  EXPECT_TRUE(logs().saw({"unknown parameter ~symmetry/filtr/s_occl"}));
  EXPECT_TRUE(logs().saw({"unknown parameter ~sesnor_frame"}));
  EXPECT_NEAR(parameter("/unknown/symmetry/filter/s_smooth"), 0.02, 1e-6) << "rejected as a whole";
  unload("/unknown");
}

TEST(SegmentationParameters, ALiveChangeKeepsOneNameAndAnInvalidOneIsRejected) {
  ros::param::set("/valid/symmetry/filter/s_occl", 0.97);
  ros::param::set("/valid/preprocessing/voxel_size", 0.012);
  ros::param::set("/valid/mode", "on_demand");
  ASSERT_TRUE(load("/valid"));
  EXPECT_NEAR(parameter("/valid/symmetry/filter/s_occl"), 0.97, 1e-6) << "the start-up value is in force";
  EXPECT_NEAR(parameter("/valid/preprocessing/voxel_size"), 0.012, 1e-6);

  // A live change through the section's server: the nested name has the new value, and there
  // is no second, flat name.
  const auto changed = reconfigure("/valid/symmetry/filter", {{"s_occl", 0.95}});
  EXPECT_NEAR(valueIn(changed, "s_occl"), 0.95, 1e-6);
  EXPECT_NEAR(parameter("/valid/symmetry/filter/s_occl"), 0.95, 1e-6);
  EXPECT_FALSE(ros::param::has("/valid/s_occl"));
  EXPECT_FALSE(ros::param::has("/valid/symmetry/s_occl"));
  EXPECT_TRUE(logs().saw({"live parameters changed", "symmetry.filter.s_occl 0.95"}));

  // NaN passes dynamic_reconfigure's clamping but not the core's validation: the change is
  // rejected as a whole (s_smooth too), logged, and the server shows the values in force.
  const auto rejected =
      reconfigure("/valid/symmetry/filter", {{"s_occl", std::numeric_limits<double>::quiet_NaN()}, {"s_smooth", 0.04}});
  EXPECT_NEAR(valueIn(rejected, "s_occl"), 0.95, 1e-6);
  EXPECT_NEAR(valueIn(rejected, "s_smooth"), 0.02, 1e-6);
  EXPECT_NEAR(parameter("/valid/symmetry/filter/s_occl"), 0.95, 1e-6);
  EXPECT_NEAR(parameter("/valid/symmetry/filter/s_smooth"), 0.02, 1e-6);
  EXPECT_TRUE(logs().saw({"rejected the live change"}));

  // Another section's server: the same single name there.
  const auto voxel = reconfigure("/valid/preprocessing", {{"voxel_size", 0.015}});
  EXPECT_NEAR(valueIn(voxel, "voxel_size"), 0.015, 1e-6);
  EXPECT_NEAR(parameter("/valid/preprocessing/voxel_size"), 0.015, 1e-6);
  EXPECT_FALSE(ros::param::has("/valid/voxel_size"));
  unload("/valid");
}

TEST(SegmentationParameters, TheTablePlaneParameterInAnotherFrameIsUsed) {
  // ~table_plane in frame "odom" (turned and shifted against "map", any scale): the node moves
  // it into the processing frame and finds what the core finds with the scene's own plane.
  const ss::Scene scene = ros_test::clutterScene(1);
  ASSERT_TRUE(scene.table_plane);
  Eigen::Isometry3d odom_in_map = Eigen::Isometry3d::Identity();
  odom_in_map.rotate(Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()));
  odom_in_map.pretranslate(Eigen::Vector3d(0.3, -0.2, 0.1));
  tf2_ros::StaticTransformBroadcaster broadcaster;
  geometry_msgs::TransformStamped transform;
  transform.header.stamp = ros::Time::now();
  transform.header.frame_id = "map";
  transform.child_frame_id = "odom";
  transform.transform.translation.x = 0.3;
  transform.transform.translation.y = -0.2;
  transform.transform.translation.z = 0.1;
  const Eigen::Quaterniond rotation(odom_in_map.rotation());
  transform.transform.rotation.z = rotation.z();
  transform.transform.rotation.w = rotation.w();
  broadcaster.sendTransform(transform);
  const Eigen::Vector4d in_odom = 2.0 * ss::transformPlane(scene.table_plane->cast<double>(), odom_in_map.inverse());
  XmlRpc::XmlRpcValue plane;
  for (int i = 0; i < 4; ++i) plane[i] = in_odom[i];
  ros::param::set("/plane/table_plane", plane);
  ros::param::set("/plane/table_plane_frame", "odom");
  ros::param::set("/plane/mode", "on_demand");
  ros::param::set("/plane/fixed_frame", "map");
  ASSERT_TRUE(load("/plane"));

  ros::NodeHandle nh;
  auto map_pub = nh.advertise<ss::OctomapMessage>("/plane/octomap", 1, true);
  const ss::OctomapMessage map = ros_test::octomapMessage(*scene.occupancy, "map");
  map_pub.publish(map);
  ASSERT_TRUE(ros_test::spinUntil([&] { return map_pub.getNumSubscribers() > 0; }, 30));
  ros::WallDuration(0.5).sleep();
  ss::SegmentCloud srv;
  srv.request.cloud = ros_test::cloudMessage(*scene.cloud, "map", ros::Time::now());
  srv.request.timeout = 5.0;
  ASSERT_TRUE(ros::service::call("/plane/segment", srv));
  ASSERT_EQ(srv.response.status, ss::SegmentCloud::Response::SUCCESS) << srv.response.message;
  EXPECT_NE(srv.response.message.find("table plane from ~table_plane (parameter)"), std::string::npos)
      << srv.response.message;

  ss::Scene received = ss::sceneFromCloudMessage(srv.request.cloud);
  received.occupancy = ss::occupancyFromMessage(map);
  received.table_plane = scene.table_plane;
  const auto core = ss::makeSegmenter("symmetry", ss::SegmentationConfig())->segment(received);
  ASSERT_EQ(srv.response.objects.objects.size(), core.segments.size());
  for (std::size_t i = 0; i < core.segments.size(); ++i) {
    const auto& indices = srv.response.objects.objects[i].indices;
    EXPECT_EQ(std::vector<int>(indices.begin(), indices.end()), core.segments[i].indices) << "segment " << i;
  }
  unload("/plane");
}

TEST(SegmentationParameters, ABadTablePlaneParameterIsLoggedAndNotUsed) {
  XmlRpc::XmlRpcValue plane;
  plane[0] = 0.0;
  plane[1] = 1.0;
  ros::param::set("/badplane/table_plane", plane);
  ros::param::set("/badplane/mode", "on_demand");
  ASSERT_TRUE(load("/badplane"));
  EXPECT_TRUE(logs().saw({"~table_plane", "4 coefficients", "got 2"}));
  unload("/badplane");
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "segmentation_parameters_test");
  ros::NodeHandle keep_node_alive;
  return RUN_ALL_TESTS();
}
