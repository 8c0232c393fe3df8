// segment_bag: segments every cloud of a bag (with the latest OctoMap before it) as fast as it
// can and writes the results - objects, labelled cloud, markers - into a new bag, stamped like
// the clouds. Reports how much faster than real time it ran.
#include <iostream>
#include <memory>
#include <string>

#include <pcl/console/print.h>
#include <pcl_msgs/ModelCoefficients.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2/buffer_core.h>
#include <tf2_eigen/tf2_eigen.h>
#include <tf2_msgs/TFMessage.h>

#include "symmetry_segmentation/SegmentCloud.h"
#include "symmetry_segmentation/command_line.h"
#include "symmetry_segmentation/ros/marker_conversion.h"
#include "symmetry_segmentation/ros/octomap_conversion.h"
#include "symmetry_segmentation/ros/result_conversion.h"
#include "symmetry_segmentation/ros/scene_assembly.h"
#include "symmetry_segmentation/ros/table_plane.h"
#include "symmetry_segmentation/segmenter.h"
#include "symmetry_segmentation/stopwatch.h"

namespace ss = symmetry_segmentation;

namespace {

const char* const kUsage =
    "usage: segment_bag <input.bag> --output OUT.bag [--cloud-topic T] [--prefix P] [--method M]\n"
    "                   [--config file.yaml] [--set section.key=value]...\n"
    "  --cloud-topic  only this sensor_msgs/PointCloud2 topic (default: every one)\n"
    "  --sensor-frame frame of the sensor, looked up in the bag's /tf and /tf_static (default:\n"
    "                 the cloud frame's origin when it is not the map's frame)\n"
    "  --up-frame     a frame whose z axis points up (base_link, odom, map), looked up in the bag's\n"
    "                 tf as the node's ~up_frame: the table is then a plane facing up\n"
    "  --prefix       namespace of the output topics (default /segmentation):\n"
    "                 P/objects, P/segmented_cloud, P/symmetry_markers (and P/label_image,\n"
    "                 mono16, for a camera's organized cloud)\n"
    "  Clouds are segmented with the latest octomap_msgs/Octomap in their frame; without one, a\n"
    "  camera's organized cloud is its own map (its depth image), and other clouds get one\n"
    "  ray-cast from the cloud frame's origin. The latest pcl_msgs/ModelCoefficients\n"
    "  before a cloud is its table plane (moved into the cloud's frame through the bag's tf);\n"
    "  without one the table is estimated. Exit code 1 if any cloud failed.\n";

struct Options {
  std::string input, output, cloud_topic, sensor_frame, up_frame, prefix = "/segmentation", method = ss::defaultMethod(), config;
  ss::ConfigValues overrides;
};

Options parse(int argc, char** argv) {
  Options options;
  ss::CommandLine arguments("segment_bag", argc, argv);
  while (arguments.next()) {
    const std::string arg = arguments.current();
    if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "--output" || arg == "-o") {
      options.output = arguments.value();
    } else if (arg == "--cloud-topic") {
      options.cloud_topic = arguments.value();
    } else if (arg == "--sensor-frame") {
      options.sensor_frame = arguments.value();
    } else if (arg == "--up-frame") {
      options.up_frame = arguments.value();
    } else if (arg == "--prefix") {
      options.prefix = arguments.value();
    } else if (arg == "--method") {
      options.method = arguments.value();
    } else if (arg == "--config") {
      options.config = arguments.value();
    } else if (arg == "--set") {
      options.overrides.push_back(arguments.assignmentValue());
    } else if (!arg.empty() && arg[0] == '-') {
      arguments.usageError("unknown option '" + arg + "'");
    } else if (options.input.empty()) {
      options.input = arg;
    } else {
      arguments.usageError("unexpected argument '" + arg + "'");
    }
  }
  if (options.input.empty()) arguments.usageError("missing <input.bag>");
  if (options.output.empty()) arguments.usageError("missing --output OUT.bag");
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  const Options options = parse(argc, argv);
  try {
    const ss::SegmentationConfig config = ss::configWithValues(
        options.config.empty() ? ss::SegmentationConfig{} : ss::loadConfigFile(options.config), options.overrides);
    const auto segmenter = ss::makeSegmenter(options.method, config);

    rosbag::Bag input;
    input.open(options.input, rosbag::bagmode::Read);
    rosbag::Bag output;
    output.open(options.output, rosbag::bagmode::Write);
    output.setCompression(rosbag::compression::LZ4);

    tf2::BufferCore transforms(ros::Duration(3600.0));
    std::shared_ptr<octomap::OcTree> map;
    std::string map_frame;
    pcl_msgs::ModelCoefficients::ConstPtr plane;
    std::size_t segmented = 0, failed = 0;
    ros::Time first, last;
    ss::Stopwatch watch;
    rosbag::View view(input);
    for (const rosbag::MessageInstance& instance : view) {
      if (first.isZero()) first = instance.getTime();
      last = instance.getTime();
      if (instance.getDataType() == ss::kOctomapDataType) {
        const auto message = instance.instantiate<ss::OctomapMessage>();
        if (!message) continue;
        try {
          map = ss::occupancyFromMessage(*message);
          map_frame = message->header.frame_id;
        } catch (const std::exception& error) {
          std::cerr << "segment_bag: skipping OctoMap at " << instance.getTime() << ": " << error.what() << "\n";
        }
        continue;
      }
      if (instance.getDataType() == "pcl_msgs/ModelCoefficients") {
        plane = instance.instantiate<pcl_msgs::ModelCoefficients>();
        if (plane && plane->values.empty()) plane.reset();  // withdrawn
        continue;
      }
      if (instance.getDataType() == "tf2_msgs/TFMessage") {
        const auto tf = instance.instantiate<tf2_msgs::TFMessage>();
        const bool is_static = instance.getTopic() == "/tf_static";
        if (tf) {
          for (const auto& transform : tf->transforms) transforms.setTransform(transform, "bag", is_static);
        }
        continue;
      }
      if (instance.getDataType() != "sensor_msgs/PointCloud2") continue;
      if (!options.cloud_topic.empty() && instance.getTopic() != options.cloud_topic) continue;
      const auto cloud = instance.instantiate<sensor_msgs::PointCloud2>();
      if (!cloud) continue;
      try {
        ss::SceneInputs inputs;
        if (map && map_frame == cloud->header.frame_id) inputs.occupancy = map;
        if (!options.sensor_frame.empty()) {
          inputs.sensor_origin = tf2::transformToEigen(transforms.lookupTransform(cloud->header.frame_id,
                                                                                  options.sensor_frame,
                                                                                  cloud->header.stamp))
                                     .translation()
                                     .cast<float>();
        } else if (!inputs.occupancy) {
          inputs.sensor_origin = Eigen::Vector3f::Zero();  // the cloud frame's origin
        }
        if (!options.up_frame.empty()) {
          inputs.up = (tf2::transformToEigen(
                           transforms.lookupTransform(cloud->header.frame_id, options.up_frame, cloud->header.stamp))
                           .linear() *
                       Eigen::Vector3d::UnitZ())
                          .cast<float>();
        }
        if (plane) {
          // As the node does: the plane's frame moved into the cloud's at the plane's stamp.
          Eigen::Vector4d coefficients = ss::planeFromCoefficients(std::vector<double>(plane->values.begin(), plane->values.end()));
          if (plane->header.frame_id != cloud->header.frame_id) {
            const ros::Time stamp = plane->header.stamp.isZero() ? cloud->header.stamp : plane->header.stamp;
            coefficients = ss::transformPlane(coefficients, tf2::transformToEigen(transforms.lookupTransform(
                                                                cloud->header.frame_id, plane->header.frame_id, stamp)));
          }
          inputs.table_plane = ss::toPlaneCoefficients(coefficients);
        }
        const ss::Scene scene = ss::assembleScene(*cloud, inputs);
        const ss::SegmentationResult result = segmenter->segment(scene);
        std_msgs::Header header = cloud->header;
        output.write(options.prefix + "/objects", instance.getTime(), ss::objectsMessage(*scene.cloud, result, header));
        output.write(options.prefix + "/segmented_cloud", instance.getTime(),
                     ss::labelledCloudMessage(*scene.cloud, result, header));
        output.write(options.prefix + "/symmetry_markers", instance.getTime(),
                     ss::symmetryMarkers(*scene.cloud, result, header));
        if (auto image = ss::labelImageMessage(*scene.cloud, result, header)) {
          output.write(options.prefix + "/label_image", instance.getTime(), *image);
        }
        std::cout << "cloud at " << cloud->header.stamp << " (" << instance.getTopic() << "): "
                  << result.segments.size() << " objects";
        for (const auto& [name, count] : result.counts) std::cout << ", " << name << " " << count;
        std::cout << "\n";
        ++segmented;
      } catch (const std::exception& error) {
        std::cerr << "segment_bag: cloud at " << cloud->header.stamp << ": " << error.what() << "\n";
        ++failed;
      }
    }
    output.close();
    const double wall = watch.elapsedMs() / 1000.0;
    const double span = (last - first).toSec();
    std::cout << "segmented " << segmented << " clouds (" << failed << " failed) in " << wall << " s; bag spans "
              << span << " s (" << (wall > 0 ? span / wall : 0.0) << "x real time); wrote " << options.output << "\n";
    return failed == 0 && segmented > 0 ? 0 : 1;
  } catch (const std::exception& error) {
    std::cerr << "segment_bag: error: " << error.what() << "\n";
    return 1;
  }
}
