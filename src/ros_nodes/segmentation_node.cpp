// segmentation_node: the SegmentationNodelet in a process of its own (same topics, service and
// parameters as the nodelet under a manager).
#include <nodelet/loader.h>
#include <ros/ros.h>

int main(int argc, char** argv) {
  ros::init(argc, argv, "segmentation");
  nodelet::Loader loader;
  const nodelet::M_string remappings(ros::names::getRemappings());
  const nodelet::V_string arguments;
  if (!loader.load(ros::this_node::getName(), "symmetry_segmentation/SegmentationNodelet", remappings, arguments)) {
    ROS_FATAL("could not load symmetry_segmentation/SegmentationNodelet");
    return 1;
  }
  ros::spin();
  return 0;
}
