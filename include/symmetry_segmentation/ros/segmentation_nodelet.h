#pragma once
// symmetry_segmentation/SegmentationNodelet: thin glue between ROS topics / the ~segment service
// and the core library's segmenter. See docs/ros_interface.md for topics, service and parameters.

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <boost/thread/recursive_mutex.hpp>
#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <nodelet_topic_tools/nodelet_lazy.h>
#include <pcl_msgs/ModelCoefficients.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "symmetry_segmentation/LiveInterfaceConfig.h"
#include "symmetry_segmentation/SegmentCloud.h"
#include "symmetry_segmentation/ros/live_parameters.h"
#include "symmetry_segmentation/ros/moved_map_cache.h"
#include "symmetry_segmentation/ros/newest_item_worker.h"
#include "symmetry_segmentation/ros/octomap_message.h"
#include "symmetry_segmentation/ros/scene_assembly.h"
#include "symmetry_segmentation/segmentation_config.h"
#include "symmetry_segmentation/segmentation_result.h"

namespace symmetry_segmentation {

class SegmentationNodelet : public nodelet_topic_tools::NodeletLazy {
 public:
  SegmentationNodelet() = default;
  ~SegmentationNodelet() override;

 private:
  struct CachedMap {
    std::shared_ptr<octomap::OcTree> tree;
    std::string frame;
  };
  /// A table plane in its own frame (from ~table_plane, the parameter or the topic).
  struct GivenPlane {
    Eigen::Vector4d plane;  ///< Unit normal.
    std::string frame;      ///< Empty: the processing frame.
    ros::Time stamp;        ///< Zero: the cloud's stamp.
    std::string source;     ///< "parameter" or "topic", for messages.
  };
  /// What one segmentation produced (or why it failed).
  struct Outcome {
    uint8_t status = SegmentCloud::Response::SUCCESS;
    std::string message;
    SegmentedObjectArray objects;
    Timings timings;
  };
  /// For /diagnostics.
  struct Statistics {
    std::size_t segmented = 0;       ///< Clouds segmented from ~input or ~segment (SUCCESS).
    std::size_t failed = 0;          ///< Segmentations that did not succeed.
    std::size_t segmented_at_last_report = 0;
    ros::WallTime last_report;
    double last_duration_ms = 0.0;   ///< Of the last segmentation, successful or not.
    uint8_t last_status = SegmentCloud::Response::SUCCESS;
    std::string last_message;
    bool any = false;
  };

  void onInit() override;
  /// NodeletLazy: an output got its first subscriber (or ~input is needed otherwise).
  void subscribe() override;
  /// NodeletLazy: the last output subscriber left; kept while ~input is still needed.
  void unsubscribe() override;
  /// ~input wanted: on_demand mode, an output subscriber, or a ~segment call waiting for a cloud.
  bool inputWanted() const;
  /// Subscribes or unsubscribes ~input as inputWanted() says (mode switch, waiting calls).
  void refreshSubscription();

  void loadInterfaceParameters();
  void loadAlgorithmParameters();
  void startLiveParameters();
  /// Applies a live change of algorithm parameters as a whole; returns the values in force.
  ConfigValues applyLiveChange(const ConfigValues& requested);
  void reconfigureInterface(LiveInterfaceConfig& live, uint32_t level);

  void cloudCallback(const sensor_msgs::PointCloud2ConstPtr& cloud);
  void octomapCallback(const OctomapMessage::ConstPtr& message);
  void tablePlaneCallback(const pcl_msgs::ModelCoefficients::ConstPtr& message);
  bool segmentService(SegmentCloud::Request& request, SegmentCloud::Response& response);
  /// Continuous mode: segments a cloud taken from the worker.
  void segmentFromTopic(sensor_msgs::PointCloud2ConstPtr& cloud);
  /// With ROS time moving backwards by more than 0.5 s (a bag restarted with --clock),
  /// transforms stamped in the "future" would be used: clears the tf buffer, the waiting cloud
  /// and the moved map.
  void handleTimeJump();
  /// The transform taking points of `source` into `target` at `stamp`, waiting up to `timeout`
  /// (wall clock). Throws RequestError(TRANSFORM_FAILED) naming `what` and both frames.
  Eigen::Isometry3d transform(const std::string& target, const std::string& source, const ros::Time& stamp,
                              const ros::Duration& timeout, const std::string& what) const;

  /// Segments `cloud` and publishes the outputs on success; never throws.
  Outcome process(const sensor_msgs::PointCloud2& cloud, const ros::Duration& timeout,
                  const std::optional<AxisAlignedBox>& roi);
  void record(const Outcome& outcome, double duration_ms);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);
  std::string processingFrame(const std::string& cloud_frame) const;
  bool continuous() const { return continuous_; }
  bool hasOutputSubscribers() const;

  // Interface parameters (read in onInit; mode also by dynamic_reconfigure).
  std::atomic<bool> continuous_{true};
  bool lazy_parameter_ = true;  // ~lazy (NodeletLazy): false keeps ~input subscribed in continuous mode
  std::string method_;
  std::string fixed_frame_;
  std::string sensor_frame_;
  std::string up_frame_;  ///< Empty: gravity unknown.
  double transform_timeout_ = 0.1;
  int max_input_points_ = 3000000;
  bool publish_object_frames_ = false;  ///< tf frame object_<id> per object with points.
  double max_rate_ = 0.0;  ///< Continuous mode: segmentations start at most this often (Hz); 0: no limit.
  int service_threads_ = 2;
  std::optional<GivenPlane> plane_parameter_;

  // Algorithm parameters in force, replaced as a whole.
  std::mutex config_mutex_;
  SegmentationConfig config_;

  // The mutex is declared first so it outlives the servers (members die in reverse order).
  boost::recursive_mutex reconfigure_mutex_;  // dynamic_reconfigure::Server takes a boost mutex
  std::unique_ptr<dynamic_reconfigure::Server<LiveInterfaceConfig>> interface_server_;
  std::vector<std::unique_ptr<LiveSection>> live_sections_;

  std::unique_ptr<tf2_ros::Buffer> tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> tf_broadcaster_;  ///< With ~publish_object_frames only.
  std::mutex frames_mutex_;
  ros::Time last_frames_stamp_;  ///< Stamp of the object frames sent last (guarded by frames_mutex_).
  // ~input: guarded by NodeletLazy's connection_mutex_.
  ros::Subscriber cloud_subscriber_;
  std::atomic<int> latest_waiters_{0};  // ~segment calls waiting for a cloud on ~input
  ros::Subscriber octomap_subscriber_;
  ros::Subscriber plane_subscriber_;
  ros::Publisher objects_publisher_;
  ros::Publisher labelled_publisher_;
  ros::Publisher markers_publisher_;
  ros::Publisher label_image_publisher_;  ///< mono16 labels, organized clouds only.
  // ~segment has a queue and threads of its own: a segmentation can take seconds, and on the
  // manager's threads (2 on 2 cores) concurrent calls would starve every other callback.
  ros::CallbackQueue service_queue_;
  ros::ServiceServer service_;
  std::unique_ptr<ros::AsyncSpinner> service_spinner_;

  // Inputs cached for the service and the frame logic.
  mutable std::mutex inputs_mutex_;
  std::condition_variable cloud_arrived_;
  sensor_msgs::PointCloud2ConstPtr latest_cloud_;
  CachedMap map_;
  std::optional<GivenPlane> plane_topic_;
  std::mutex time_mutex_;
  ros::Time last_time_;
  std::atomic<bool> stopping_{false};

  std::unique_ptr<MovedMapCache> moved_maps_;
  // Continuous mode: one pending cloud at most (newer replaces older), one worker thread.
  std::unique_ptr<NewestItemWorker<sensor_msgs::PointCloud2ConstPtr>> worker_;

  std::mutex statistics_mutex_;
  Statistics statistics_;
  std::unique_ptr<diagnostic_updater::Updater> diagnostics_;
  ros::WallTimer diagnostics_timer_;
};

}  // namespace symmetry_segmentation
