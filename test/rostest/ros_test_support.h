#pragma once
// Shared by the rostest nodes: a generated scene as messages, and waiting for messages.
#include <functional>

#include <octomap/OcTree.h>
#include <pcl_conversions/pcl_conversions.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>

#include "symmetry_segmentation/ros/octomap_conversion.h"
#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/synthetic/scene_generator.h"

namespace ros_test {

inline symmetry_segmentation::Scene clutterScene(uint32_t seed) {
  symmetry_segmentation::synthetic::GeneratorOptions options;
  options.kind = symmetry_segmentation::synthetic::SceneKind::Clutter;
  options.seed = seed;
  return symmetry_segmentation::synthetic::generateScene(options);
}

inline sensor_msgs::PointCloud2 cloudMessage(const symmetry_segmentation::Cloud& cloud, const std::string& frame,
                                            const ros::Time& stamp) {
  sensor_msgs::PointCloud2 message;
  pcl::toROSMsg(cloud, message);
  message.header.frame_id = frame;
  message.header.stamp = stamp;
  return message;
}

inline symmetry_segmentation::OctomapMessage octomapMessage(const octomap::OcTree& tree, const std::string& frame) {
  auto message = symmetry_segmentation::binaryMessageFromTree(tree);
  message.header.frame_id = frame;
  message.header.stamp = ros::Time::now();
  return message;
}

/// Spins until `done` or `seconds` pass; returns done().
inline bool spinUntil(const std::function<bool()>& done, double seconds) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(seconds);
  while (ros::ok() && !done() && ros::WallTime::now() < deadline) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  return done();
}

}  // namespace ros_test
