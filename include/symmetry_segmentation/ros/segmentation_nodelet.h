#pragma once
// symmetry_segmentation/SegmentationNodelet: thin glue between ROS topics / the ~segment service
// and the core library's segmenter. See docs/ros_interface.md for topics, service and parameters.

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include <Eigen/Geometry>
#include <dynamic_reconfigure/server.h>
#include <nodelet/nodelet.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/message_filter.h>
#include <tf2_ros/transform_listener.h>

#include "symmetry_segmentation/SegmentCloud.h"
#include "symmetry_segmentation/LiveParametersConfig.h"
#include "symmetry_segmentation/ros/octomap_message.h"
#include "symmetry_segmentation/ros/scene_assembly.h"
#include "symmetry_segmentation/segmentation_config.h"
#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

class SegmentationNodelet : public nodelet::Nodelet {
 public:
  SegmentationNodelet() = default;
  ~SegmentationNodelet() override;

 private:
  struct CachedMap {
    std::shared_ptr<octomap::OcTree> tree;
    std::string frame;
  };
  /// The cached map moved into a processing frame over a region (maps from another frame).
  struct MovedMap {
    std::shared_ptr<octomap::OcTree> source;
    std::string frame;
    Eigen::Isometry3d source_to_frame = Eigen::Isometry3d::Identity();
    Eigen::AlignedBox3d region;
    std::shared_ptr<octomap::OcTree> tree;
  };
  /// What one segmentation produced (or why it failed).
  struct Outcome {
    uint8_t status = SegmentCloud::Response::SUCCESS;
    std::string message;
    SegmentedObjectArray objects;
    Timings timings;
  };

  void onInit() override;
  void loadParameters();
  void cloudCallback(const sensor_msgs::PointCloud2ConstPtr& cloud);
  void transformedCloudCallback(const sensor_msgs::PointCloud2ConstPtr& cloud);
  void transformFailureCallback(const sensor_msgs::PointCloud2ConstPtr& cloud,
                                tf2_ros::filter_failure_reasons::FilterFailureReason reason);
  void octomapCallback(const OctomapMessage::ConstPtr& message);
  bool segmentService(SegmentCloud::Request& request, SegmentCloud::Response& response);
  void reconfigure(symmetry_segmentation::LiveParametersConfig& live, uint32_t level);
  void workerLoop();
  /// Subscribes ~input while it is needed (on_demand mode, an output subscriber, or a ~segment
  /// call waiting for a cloud), unsubscribes otherwise.
  void updateInputSubscription();
  /// With ROS time moving backwards by more than 0.5 s (a bag restarted with --clock), transforms stamped in the
  /// "future" would be used or block the filter: clears the tf buffer, the filter's queue and the pending cloud.
  void handleTimeJump();
  /// The cached map moved into `frame` (by `map_to_frame`) over a region containing `box`.
  std::shared_ptr<octomap::OcTree> movedMap(const std::shared_ptr<octomap::OcTree>& map, const std::string& frame,
                                            const Eigen::Isometry3d& map_to_frame, const Eigen::AlignedBox3d& box);

  /// Segments `cloud` and publishes the outputs on success; never throws.
  Outcome process(const sensor_msgs::PointCloud2& cloud, const ros::Duration& timeout,
                  const std::optional<AxisAlignedBox>& roi);
  std::string processingFrame(const std::string& cloud_frame) const;
  bool continuous() const { return continuous_; }
  bool hasOutputSubscribers() const;

  // Parameters (read in onInit; mode and the live-tuned values also by dynamic_reconfigure).
  std::atomic<bool> continuous_{true};
  std::string method_;
  std::string fixed_frame_;
  std::string sensor_frame_;
  double transform_timeout_ = 0.1;
  int max_input_points_ = 3000000;
  std::mutex config_mutex_;
  SegmentationConfig config_;

  // The mutex is declared first so it outlives the server (members die in reverse order).
  boost::recursive_mutex reconfigure_mutex_;  // dynamic_reconfigure::Server takes a boost mutex
  std::unique_ptr<dynamic_reconfigure::Server<symmetry_segmentation::LiveParametersConfig>> reconfigure_server_;

  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  std::unique_ptr<tf2_ros::MessageFilter<sensor_msgs::PointCloud2>> tf_filter_;
  std::mutex subscription_mutex_;  // cloud_subscriber_ and latest_waiters_
  ros::Subscriber cloud_subscriber_;
  int latest_waiters_ = 0;  // ~segment calls waiting for a cloud on ~input
  ros::Subscriber octomap_subscriber_;
  ros::Publisher objects_publisher_;
  ros::Publisher labelled_publisher_;
  ros::Publisher markers_publisher_;
  // ~segment has a queue and threads of its own: a segmentation can take seconds, and on the
  // manager's threads (2 on 2 cores) concurrent calls would starve every other callback.
  ros::CallbackQueue service_queue_;
  ros::ServiceServer service_;
  std::unique_ptr<ros::AsyncSpinner> service_spinner_;
  int service_threads_ = 2;

  // Inputs cached for the service and the frame logic.
  mutable std::mutex inputs_mutex_;
  std::condition_variable cloud_arrived_;
  sensor_msgs::PointCloud2ConstPtr latest_cloud_;
  CachedMap map_;
  std::mutex moved_map_mutex_;
  MovedMap moved_map_;
  std::mutex time_mutex_;
  ros::Time last_time_;

  // Continuous mode: one pending cloud at most (newer replaces older), one worker thread.
  std::mutex queue_mutex_;
  std::condition_variable queue_changed_;
  sensor_msgs::PointCloud2ConstPtr pending_cloud_;
  std::atomic<bool> stopping_{false};  // also read by the service under inputs_mutex_
  std::thread worker_;
  std::atomic<std::size_t> dropped_clouds_{0};
};

}  // namespace symmetry_segmentation
