// scene_to_bag: writes a scene (cloud, OctoMap as octomap_msgs/Octomap, tf) into a rosbag, as a
// robot with a fused-cloud mapper and octomap_server would have recorded it.
#include <iostream>
#include <numeric>
#include <string>

#include <geometry_msgs/TransformStamped.h>
#include <octomap/OcTree.h>
#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl_conversions/pcl_conversions.h>
#include <pcl_msgs/ModelCoefficients.h>
#include <rosbag/bag.h>
#include <tf2_msgs/TFMessage.h>

#include "symmetry_segmentation/command_line.h"
#include "symmetry_segmentation/ros/octomap_conversion.h"
#include "symmetry_segmentation/scene_io.h"
#include "symmetry_segmentation/voxel_grid.h"

namespace ss = symmetry_segmentation;

namespace {

const char* const kUsage =
    "usage: scene_to_bag <scene> --output FILE.bag [--clouds N] [--rate HZ] [--voxel M] [--frame F]\n"
    "                    [--camera-frame F] [--cloud-topic T] [--octomap-topic T] [--plane-topic T]\n"
    "                    [--full-octomap]\n"
    "  <scene>          scene directory (cloud.ply, occupancy.bt, scene_info.yaml) or cloud file;\n"
    "                   without an OctoMap (a camera frame) no map is written\n"
    "  --clouds         cloud messages to write (default 3), one every 1/rate s\n"
    "  --rate           cloud rate in Hz (default 1)\n"
    "  --voxel          downsample the cloud to this leaf size in m first (default 0: keep all)\n"
    "  --frame          frame of the cloud and the map (default map)\n"
    "  --camera-frame   static tf child at the first sensor origin (default camera)\n"
    "  --cloud-topic    default /kinfu/cloud;  --octomap-topic default /octomap_binary\n"
    "  --plane-topic    the scene's table_plane.txt, if any, latched as pcl_msgs/ModelCoefficients\n"
    "                   in the map frame (default /table_plane; empty: not written)\n"
    "  --full-octomap   write the map as a full (.ot) message instead of a binary one\n";

struct Options {
  std::string scene, output, frame = "map", camera_frame = "camera";
  std::string cloud_topic = "/kinfu/cloud", octomap_topic = "/octomap_binary", plane_topic = "/table_plane";
  int clouds = 3;
  double rate = 1.0, voxel = 0.0;
  bool full_octomap = false;
};

Options parse(int argc, char** argv) {
  Options options;
  ss::CommandLine arguments("scene_to_bag", argc, argv);
  while (arguments.next()) {
    const std::string arg = arguments.current();
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "--output" || arg == "-o") {
      options.output = arguments.value();
    } else if (arg == "--clouds") {
      options.clouds = arguments.intValue(1, 100000);
    } else if (arg == "--rate") {
      options.rate = arguments.numberValue();
    } else if (arg == "--voxel") {
      options.voxel = arguments.numberValue();
    } else if (arg == "--frame") {
      options.frame = arguments.value();
    } else if (arg == "--camera-frame") {
      options.camera_frame = arguments.value();
    } else if (arg == "--cloud-topic") {
      options.cloud_topic = arguments.value();
    } else if (arg == "--octomap-topic") {
      options.octomap_topic = arguments.value();
    } else if (arg == "--plane-topic") {
      options.plane_topic = arguments.value();
    } else if (arg == "--full-octomap") {
      options.full_octomap = true;
    } else if (!arg.empty() && arg[0] == '-') {
      arguments.usageError("unknown option '" + arg + "'");
    } else if (options.scene.empty()) {
      options.scene = arg;
    } else {
      arguments.usageError("unexpected argument '" + arg + "'");
    }
  }
  if (options.scene.empty()) arguments.usageError("missing <scene>");
  if (options.output.empty()) arguments.usageError("missing --output FILE.bag");
  if (!(options.rate > 0.0)) arguments.usageError("--rate must be positive");
  if (options.voxel < 0.0) arguments.usageError("--voxel must not be negative");
  return options;
}

// rosbag uses a given connection header verbatim: it must carry the type fields too.
template <class M>
boost::shared_ptr<ros::M_string> latched() {
  auto header = boost::make_shared<ros::M_string>();
  (*header)["type"] = ros::message_traits::datatype<M>();
  (*header)["md5sum"] = ros::message_traits::md5sum<M>();
  (*header)["message_definition"] = ros::message_traits::definition<M>();
  (*header)["callerid"] = "/scene_to_bag";
  (*header)["latching"] = "1";
  return header;
}

}  // namespace

int main(int argc, char** argv) {
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  const Options options = parse(argc, argv);
  try {
    const ss::Scene scene = ss::loadScene(options.scene, {true, false});
    ss::Cloud cloud = *scene.cloud;
    if (options.voxel > 0.0) {
      std::vector<int> all;
      for (std::size_t i = 0; i < cloud.size(); ++i) {
        const auto& p = cloud[i];
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) all.push_back(static_cast<int>(i));
      }
      cloud = *ss::voxelDownsample(cloud, all, static_cast<float>(options.voxel), scene.has_normals).cloud;
    }
    const ros::Time start(1000, 0);  // fixed, so the same scene gives the same bag

    rosbag::Bag bag;
    bag.open(options.output, rosbag::bagmode::Write);
    bag.setCompression(rosbag::compression::BZ2);

    tf2_msgs::TFMessage tf;
    geometry_msgs::TransformStamped camera;
    camera.header.stamp = start;
    camera.header.frame_id = options.frame;
    camera.child_frame_id = options.camera_frame;
    const Eigen::Vector3f origin = scene.sensor_origins.empty() ? Eigen::Vector3f::Zero() : scene.sensor_origins[0];
    camera.transform.translation.x = origin.x();
    camera.transform.translation.y = origin.y();
    camera.transform.translation.z = origin.z();
    camera.transform.rotation.w = 1.0;
    tf.transforms.push_back(camera);
    bag.write("/tf_static", start, tf, latched<tf2_msgs::TFMessage>());

    // A single view (a camera frame) has no map: the node takes free space from its depth image.
    if (scene.occupancy) {
      ss::OctomapMessage map = options.full_octomap ? ss::fullMessageFromTree(*scene.occupancy)
                                                    : ss::binaryMessageFromTree(*scene.occupancy);
      map.header.frame_id = options.frame;
      map.header.stamp = start;
      bag.write(options.octomap_topic, start, map, latched<ss::OctomapMessage>());
    }

    if (scene.table_plane && !options.plane_topic.empty()) {
      pcl_msgs::ModelCoefficients plane;
      plane.header.frame_id = options.frame;
      plane.header.stamp = start;
      plane.values.assign(scene.table_plane->data(), scene.table_plane->data() + 4);
      bag.write(options.plane_topic, start, plane, latched<pcl_msgs::ModelCoefficients>());
    }

    sensor_msgs::PointCloud2 message;
    if (scene.has_normals) {
      pcl::toROSMsg(cloud, message);
    } else {  // as a camera driver sends it: no normal fields (the node would take them as given)
      pcl::PointCloud<pcl::PointXYZRGB> plain;
      pcl::copyPointCloud(cloud, plain);
      pcl::toROSMsg(plain, message);
    }
    message.header.frame_id = options.frame;
    for (int i = 0; i < options.clouds; ++i) {
      const ros::Time stamp = start + ros::Duration(0.05 + i / options.rate);
      message.header.stamp = stamp;
      message.header.seq = static_cast<uint32_t>(i);
      bag.write(options.cloud_topic, stamp, message);
    }
    bag.close();
    std::cout << "wrote " << options.output << ": " << options.clouds << " clouds of " << cloud.size()
              << " points (" << cloud.width << " x " << cloud.height << ") on " << options.cloud_topic
              << (scene.occupancy ? ", OctoMap on " + options.octomap_topic : ", no OctoMap (single view)")
              << (scene.table_plane && !options.plane_topic.empty() ? ", table plane on " + options.plane_topic : "")
              << ", tf " << options.frame << " -> " << options.camera_frame << "\n";
    return 0;
  } catch (const std::exception& error) {
    std::cerr << "scene_to_bag: error: " << error.what() << "\n";
    return 1;
  }
}
