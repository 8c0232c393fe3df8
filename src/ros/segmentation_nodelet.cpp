#include "symmetry_segmentation/ros/segmentation_nodelet.h"

#include <chrono>
#include <iomanip>
#include <sstream>

#include <pcl/console/print.h>
#include <pluginlib/class_list_macros.hpp>
#include <tf2_eigen/tf2_eigen.h>
#include <visualization_msgs/MarkerArray.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/ros/cloud_conversion.h"
#include "symmetry_segmentation/ros/marker_conversion.h"
#include "symmetry_segmentation/ros/octomap_conversion.h"
#include "symmetry_segmentation/ros/parameters.h"
#include "symmetry_segmentation/ros/result_conversion.h"
#include "symmetry_segmentation/segmenter.h"
#include "symmetry_segmentation/stopwatch.h"

namespace symmetry_segmentation {

namespace {
using Response = SegmentCloud::Response;

constexpr double kTimeJumpTolerance = 0.5;  // s: smaller jumps back are not acted on

// Waits for a transform against the wall clock: with use_sim_time a stopped player stops the
// clock, and tf2's own timeout (in ROS time) would then never expire.
bool waitForTransform(const tf2_ros::Buffer& buffer, const std::string& target, const std::string& source,
                      const ros::Time& stamp, const ros::Duration& timeout, std::string* error) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(std::max(0.0, timeout.toSec()));
  while (true) {
    error->clear();
    if (buffer.canTransform(target, source, stamp, error)) return true;
    if (ros::WallTime::now() >= deadline || !ros::ok()) return false;
    ros::WallDuration(0.01).sleep();
  }
}
}

SegmentationNodelet::~SegmentationNodelet() {
  {
    std::lock_guard<std::mutex> lock(queue_mutex_);
    stopping_ = true;
  }
  queue_changed_.notify_all();
  {
    std::lock_guard<std::mutex> lock(inputs_mutex_);  // a waiting ~segment call sees stopping_
  }
  cloud_arrived_.notify_all();
  if (worker_.joinable()) worker_.join();
  // Callbacks may still be running on other threads while members are destroyed (in reverse
  // order of declaration). Stop every source of callbacks first, let ~segment calls in progress
  // finish (stopping the spinner joins its threads), and take the tf listener's thread down
  // before the filter it feeds: that thread calls into the filter, whose mutexes must not be
  // gone (a boost::lock_error otherwise).
  service_.shutdown();
  if (service_spinner_) service_spinner_->stop();
  reconfigure_server_.reset();
  {
    std::lock_guard<std::mutex> lock(subscription_mutex_);
    cloud_subscriber_.shutdown();
  }
  octomap_subscriber_.shutdown();
  tf_listener_.reset();
  tf_filter_.reset();
}

void SegmentationNodelet::loadParameters() {
  ros::NodeHandle& pnh = getPrivateNodeHandle();
  std::string mode;
  pnh.param<std::string>("mode", mode, "continuous");
  if (mode != "continuous" && mode != "on_demand") {
    NODELET_ERROR("~mode '%s' is neither 'continuous' nor 'on_demand'; using 'continuous'", mode.c_str());
    mode = "continuous";
  }
  continuous_ = mode == "continuous";
  pnh.param<std::string>("method", method_, defaultMethod());
  pnh.param<std::string>("fixed_frame", fixed_frame_, "");
  pnh.param<std::string>("sensor_frame", sensor_frame_, "");
  pnh.param("transform_timeout", transform_timeout_, 0.1);
  pnh.param("max_input_points", max_input_points_, 3000000);
  pnh.param("service_threads", service_threads_, 2);
  if (service_threads_ < 1) {
    NODELET_ERROR("~service_threads %d is less than 1; using 1", service_threads_);
    service_threads_ = 1;
  }
  if (max_input_points_ < 0) {
    NODELET_ERROR("~max_input_points %d is negative; using 0 (no limit)", max_input_points_);
    max_input_points_ = 0;
  }

  SegmentationConfig config;
  std::vector<std::string> errors;
  for (const auto& section : configSections()) {
    XmlRpc::XmlRpcValue value;
    if (pnh.getParam(section, value)) applyParameters(section, value, config, errors);
  }
  for (const auto& error : errors) NODELET_ERROR("ignoring parameter %s", error.c_str());
  try {
    makeSegmenter(method_, config);
  } catch (const std::exception& error) {
    NODELET_ERROR("%s; using method '%s'", error.what(), defaultMethod().c_str());
    method_ = defaultMethod();
  }
  std::lock_guard<std::mutex> lock(config_mutex_);
  config_ = config;
}

void SegmentationNodelet::onInit() {
  // PCL warns for every field a cloud lacks (e.g. normals): expected here, so errors only.
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  loadParameters();
  ros::NodeHandle& pnh = getPrivateNodeHandle();

  tf_buffer_ = std::make_unique<tf2_ros::Buffer>();
  tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_, getNodeHandle());
  // The filter delivers clouds once their transform into the processing frame is there; its
  // queue is short so a missing transform never builds up a backlog.
  tf_filter_ = std::make_unique<tf2_ros::MessageFilter<sensor_msgs::PointCloud2>>(
      *tf_buffer_, fixed_frame_.empty() ? std::string("map") : fixed_frame_, 2, pnh);
  tf_filter_->registerCallback(&SegmentationNodelet::transformedCloudCallback, this);
  tf_filter_->registerFailureCallback(
      boost::bind(&SegmentationNodelet::transformFailureCallback, this, boost::placeholders::_1, boost::placeholders::_2));

  // Lazy like pcl_ros nodelets: ~input is subscribed only while someone listens (continuous).
  const ros::SubscriberStatusCallback connection = boost::bind(&SegmentationNodelet::updateInputSubscription, this);
  objects_publisher_ = pnh.advertise<SegmentedObjectArray>("objects", 1, connection, connection);
  labelled_publisher_ = pnh.advertise<sensor_msgs::PointCloud2>("segmented_cloud", 1, connection, connection);
  markers_publisher_ = pnh.advertise<visualization_msgs::MarkerArray>("symmetry_markers", 1, connection, connection);
  // The service runs on threads of its own, so long segmentations never block the subscriber
  // callbacks (nor other nodelets of the manager).
  ros::NodeHandle service_nh(pnh);
  service_nh.setCallbackQueue(&service_queue_);
  service_ = service_nh.advertiseService("segment", &SegmentationNodelet::segmentService, this);
  service_spinner_ = std::make_unique<ros::AsyncSpinner>(static_cast<uint32_t>(service_threads_), &service_queue_);
  service_spinner_->start();
  updateInputSubscription();
  octomap_subscriber_ = pnh.subscribe("octomap", 1, &SegmentationNodelet::octomapCallback, this);
  worker_ = std::thread(&SegmentationNodelet::workerLoop, this);  // idles in on_demand mode

  // Live tuning. The server starts from the values loaded above (config file, ~mode), not
  // from the .cfg defaults: updateConfig before setCallback.
  reconfigure_server_ = std::make_unique<dynamic_reconfigure::Server<symmetry_segmentation::LiveParametersConfig>>(
      reconfigure_mutex_, getMTPrivateNodeHandle());
  symmetry_segmentation::LiveParametersConfig live;
  {
    std::lock_guard<std::mutex> lock(config_mutex_);
    live.mode = continuous() ? "continuous" : "on_demand";
    live.voxel_size = config_.preprocessing.voxel_size;
    live.s_occl = config_.symmetry.filter.s_occl;
    live.s_smooth = config_.symmetry.filter.s_smooth;
    live.lambda_smooth = config_.symmetry.cut.lambda_smooth;
    live.lambda_sym = config_.symmetry.cut.lambda_sym;
  }
  reconfigure_server_->updateConfig(live);
  reconfigure_server_->setCallback(boost::bind(&SegmentationNodelet::reconfigure, this, boost::placeholders::_1,
                                               boost::placeholders::_2));
  NODELET_INFO("symmetry segmentation ready: mode %s, method %s, fixed frame '%s', sensor frame '%s'",
               continuous() ? "continuous" : "on_demand", method_.c_str(), fixed_frame_.c_str(),
               sensor_frame_.c_str());
}

void SegmentationNodelet::reconfigure(symmetry_segmentation::LiveParametersConfig& live, uint32_t) {
  SegmentationConfig config;
  {
    std::lock_guard<std::mutex> lock(config_mutex_);
    config = config_;
  }
  const std::pair<const char*, double> values[] = {{"preprocessing.voxel_size", live.voxel_size},
                                                   {"symmetry.filter.s_occl", live.s_occl},
                                                   {"symmetry.filter.s_smooth", live.s_smooth},
                                                   {"symmetry.cut.lambda_smooth", live.lambda_smooth},
                                                   {"symmetry.cut.lambda_sym", live.lambda_sym}};
  for (const auto& [key, value] : values) {
    try {
      std::ostringstream text;
      text << std::setprecision(17) << value;
      setConfigValue(config, key, text.str());
    } catch (const std::exception& error) {
      NODELET_ERROR("reconfigure: ignoring %s = %g: %s", key, value, error.what());
    }
  }
  {
    std::lock_guard<std::mutex> lock(config_mutex_);
    config_ = config;
  }
  if (live.mode != "continuous" && live.mode != "on_demand") {
    NODELET_ERROR("reconfigure: mode '%s' is neither 'continuous' nor 'on_demand'; unchanged", live.mode.c_str());
    live.mode = continuous() ? "continuous" : "on_demand";
  }
  continuous_ = live.mode == "continuous";
  updateInputSubscription();
  NODELET_INFO("reconfigured: mode %s, voxel_size %g, s_occl %g, s_smooth %g, lambda_smooth %g, lambda_sym %g",
               live.mode.c_str(), live.voxel_size, live.s_occl, live.s_smooth, live.lambda_smooth, live.lambda_sym);
}

bool SegmentationNodelet::hasOutputSubscribers() const {
  return objects_publisher_.getNumSubscribers() > 0 || labelled_publisher_.getNumSubscribers() > 0 ||
         markers_publisher_.getNumSubscribers() > 0;
}

std::string SegmentationNodelet::processingFrame(const std::string& cloud_frame) const {
  if (!fixed_frame_.empty()) return fixed_frame_;
  std::lock_guard<std::mutex> lock(inputs_mutex_);
  return map_.tree ? map_.frame : cloud_frame;
}

void SegmentationNodelet::updateInputSubscription() {
  std::lock_guard<std::mutex> lock(subscription_mutex_);
  if (stopping_) return;
  const bool wanted = !continuous() || hasOutputSubscribers() || latest_waiters_ > 0;
  if (wanted && !cloud_subscriber_) {
    cloud_subscriber_ = getPrivateNodeHandle().subscribe("input", 1, &SegmentationNodelet::cloudCallback, this);
    NODELET_DEBUG("subscribed to %s", cloud_subscriber_.getTopic().c_str());
  } else if (!wanted && cloud_subscriber_) {
    NODELET_DEBUG("unsubscribing from %s: nobody listens", cloud_subscriber_.getTopic().c_str());
    cloud_subscriber_.shutdown();
  }
}

void SegmentationNodelet::handleTimeJump() {
  ros::Duration back;
  {
    // Read under the lock: concurrent callers must not see each other's reads out of order.
    std::lock_guard<std::mutex> lock(time_mutex_);
    const ros::Time now = ros::Time::now();
    if (now < last_time_) back = last_time_ - now;
    last_time_ = now;
  }
  // rosbag play's clock jitters back by milliseconds when the player runs late: transforms that
  // little ahead do no harm (tf2's listener still clears its buffer on those by itself).
  if (back <= ros::Duration(kTimeJumpTolerance)) return;
  NODELET_WARN("ROS time moved backwards by %.3f s (restarted bag?): clearing the tf buffer", back.toSec());
  tf_buffer_->clear();
  tf_filter_->clear();
  {
    // A cloud waiting from before the jump is stamped in the new "future": no transform for it.
    std::lock_guard<std::mutex> lock(queue_mutex_);
    pending_cloud_.reset();
  }
  std::lock_guard<std::mutex> lock(moved_map_mutex_);
  moved_map_ = MovedMap();
}

void SegmentationNodelet::cloudCallback(const sensor_msgs::PointCloud2ConstPtr& cloud) {
  handleTimeJump();
  CloudCheckOptions check;
  check.max_points = static_cast<std::size_t>(max_input_points_);
  const std::string problem = cloudMessageProblem(*cloud, check);
  if (!problem.empty()) {
    // Not cached for ~segment and not segmented: nothing is published for it.
    NODELET_WARN_THROTTLE(5.0, "ignoring cloud on ~input: %s", problem.c_str());
    return;
  }
  {
    std::lock_guard<std::mutex> lock(inputs_mutex_);
    latest_cloud_ = cloud;
  }
  cloud_arrived_.notify_all();
  // Lazy: in continuous mode without anyone listening, caching the pointer is all we do.
  if (!continuous() || !hasOutputSubscribers()) return;
  const std::string target = processingFrame(cloud->header.frame_id);
  if (target == cloud->header.frame_id) {
    transformedCloudCallback(cloud);
    return;
  }
  if (tf_filter_->getTargetFramesString() != target) tf_filter_->setTargetFrame(target);
  tf_filter_->add(cloud);
}

void SegmentationNodelet::transformedCloudCallback(const sensor_msgs::PointCloud2ConstPtr& cloud) {
  {
    std::lock_guard<std::mutex> lock(queue_mutex_);
    if (pending_cloud_) ++dropped_clouds_;  // busy: the newest cloud replaces the stale one
    pending_cloud_ = cloud;
  }
  queue_changed_.notify_one();
}

void SegmentationNodelet::transformFailureCallback(const sensor_msgs::PointCloud2ConstPtr& cloud,
                                                   tf2_ros::filter_failure_reasons::FilterFailureReason reason) {
  NODELET_WARN_THROTTLE(5.0, "dropping cloud in frame '%s' at %.3f: no transform into '%s' (%s)",
                        cloud->header.frame_id.c_str(), cloud->header.stamp.toSec(),
                        tf_filter_->getTargetFramesString().c_str(),
                        reason == tf2_ros::filter_failure_reasons::OutTheBack ? "too old"
                        : reason == tf2_ros::filter_failure_reasons::EmptyFrameID ? "empty frame id"
                                                                                    : "transform unavailable");
}

void SegmentationNodelet::octomapCallback(const OctomapMessage::ConstPtr& message) {
  handleTimeJump();
  try {
    if (message->header.frame_id.empty()) throw InputError("header.frame_id is empty: the map's frame is unknown");
    auto tree = occupancyFromMessage(*message);
    std::lock_guard<std::mutex> lock(inputs_mutex_);
    map_.tree = std::move(tree);
    map_.frame = message->header.frame_id;
  } catch (const std::exception& error) {
    NODELET_ERROR_THROTTLE(5.0, "ignoring OctoMap: %s", error.what());
  }
}

void SegmentationNodelet::workerLoop() {
  while (true) {
    sensor_msgs::PointCloud2ConstPtr cloud;
    {
      std::unique_lock<std::mutex> lock(queue_mutex_);
      queue_changed_.wait(lock, [this] { return stopping_ || pending_cloud_; });
      if (stopping_) return;
      cloud.swap(pending_cloud_);
    }
    if (!continuous() || !hasOutputSubscribers()) continue;
    const Outcome outcome = process(*cloud, ros::Duration(transform_timeout_), std::nullopt);
    if (outcome.status == Response::INVALID_INPUT) {
      NODELET_WARN_THROTTLE(5.0, "cloud not segmented: %s", outcome.message.c_str());
    } else if (outcome.status != Response::SUCCESS) {
      NODELET_ERROR_THROTTLE(5.0, "segmentation failed (status %d): %s", outcome.status, outcome.message.c_str());
    }
  }
}

SegmentationNodelet::Outcome SegmentationNodelet::process(const sensor_msgs::PointCloud2& cloud,
                                                          const ros::Duration& timeout,
                                                          const std::optional<AxisAlignedBox>& roi) {
  Outcome outcome;
  try {
    Stopwatch prepare_watch;
    CloudCheckOptions check;
    check.max_points = static_cast<std::size_t>(max_input_points_);
    const std::string problem = cloudMessageProblem(cloud, check);
    if (!problem.empty()) throw RequestError(Response::INVALID_INPUT, problem);
    const std::string frame = processingFrame(cloud.header.frame_id);
    SceneInputs inputs;
    inputs.region_of_interest = roi;
    const ros::Time stamp = cloud.header.stamp;
    if (frame != cloud.header.frame_id) {
      std::string error;
      if (!waitForTransform(*tf_buffer_, frame, cloud.header.frame_id, stamp, timeout, &error)) {
        throw RequestError(Response::TRANSFORM_FAILED, "no transform from cloud frame '" + cloud.header.frame_id +
                                                           "' to processing frame '" + frame + "': " + error);
      }
      inputs.cloud_to_processing = tf2::transformToEigen(tf_buffer_->lookupTransform(frame, cloud.header.frame_id, stamp));
    }
    CachedMap map;
    {
      std::lock_guard<std::mutex> lock(inputs_mutex_);
      map = map_;
    }
    if (map.tree && map.frame == frame) {
      inputs.occupancy = map.tree;
    } else if (map.tree) {
      // A map in another frame is moved into the processing frame with the transform at the
      // cloud's stamp (where the world was relative to the processing frame when it was seen).
      std::string error;
      if (!waitForTransform(*tf_buffer_, frame, map.frame, stamp, timeout, &error)) {
        throw RequestError(Response::TRANSFORM_FAILED, "no transform from the OctoMap's frame '" + map.frame +
                                                           "' to processing frame '" + frame + "': " + error);
      }
      const Eigen::Isometry3d map_to_frame = tf2::transformToEigen(tf_buffer_->lookupTransform(frame, map.frame, stamp));
      inputs.occupancy_for_region = [this, map, frame, map_to_frame](const Eigen::AlignedBox3d& box) {
        return movedMap(map.tree, frame, map_to_frame, box);
      };
    }
    {
      if (!sensor_frame_.empty()) {
        std::string error;
        if (!waitForTransform(*tf_buffer_, frame, sensor_frame_, stamp, timeout, &error)) {
          throw RequestError(Response::TRANSFORM_FAILED, "no transform from sensor frame '" + sensor_frame_ +
                                                             "' to processing frame '" + frame + "': " + error);
        }
        inputs.sensor_origin = tf2::transformToEigen(tf_buffer_->lookupTransform(frame, sensor_frame_, stamp))
                                   .translation()
                                   .cast<float>();
      } else if (frame != cloud.header.frame_id) {
        // The cloud's own viewpoint: the origin of the frame it was measured in.
        inputs.sensor_origin = inputs.cloud_to_processing.translation().cast<float>();
      }
    }
    const Scene scene = assembleScene(cloud, inputs);
    const double prepare_ms = prepare_watch.elapsedMs();

    SegmentationConfig config;
    {
      std::lock_guard<std::mutex> lock(config_mutex_);
      config = config_;
    }
    SegmentationResult result;
    try {
      result = makeSegmenter(method_, config)->segment(scene);
    } catch (const InputError& error) {
      throw RequestError(Response::INVALID_INPUT, error.what());
    } catch (const std::exception& error) {
      throw RequestError(Response::SEGMENTATION_FAILED, error.what());
    }

    Stopwatch publish_watch;
    std_msgs::Header header;
    header.stamp = stamp;
    header.frame_id = frame;
    outcome.objects = objectsMessage(*scene.cloud, result, header);
    objects_publisher_.publish(outcome.objects);
    if (labelled_publisher_.getNumSubscribers() > 0) {
      labelled_publisher_.publish(labelledCloudMessage(*scene.cloud, result, header));
    }
    if (markers_publisher_.getNumSubscribers() > 0) {
      markers_publisher_.publish(symmetryMarkers(*scene.cloud, result, header));
    }
    outcome.timings.emplace_back("prepare", prepare_ms);
    for (const auto& stage : result.timing_ms) {
      if (stage.first != "total") outcome.timings.push_back(stage);
    }
    outcome.timings.emplace_back("publish", publish_watch.elapsedMs());
    outcome.timings.emplace_back("total", prepare_watch.elapsedMs());
    outcome.message = std::to_string(result.segments.size()) + " objects from " +
                      std::to_string(scene.size()) + " points in frame '" + frame + "'";
  } catch (const RequestError& error) {
    outcome.status = error.status();
    outcome.message = error.what();
  } catch (const std::exception& error) {
    outcome.status = Response::SEGMENTATION_FAILED;
    outcome.message = error.what();
  }
  return outcome;
}

std::shared_ptr<octomap::OcTree> SegmentationNodelet::movedMap(const std::shared_ptr<octomap::OcTree>& map,
                                                               const std::string& frame,
                                                               const Eigen::Isometry3d& map_to_frame,
                                                               const Eigen::AlignedBox3d& box) {
  // One entry, computed under the lock: concurrent calls for the same map wait for it once.
  std::lock_guard<std::mutex> lock(moved_map_mutex_);
  if (moved_map_.tree && moved_map_.source == map && moved_map_.frame == frame &&
      moved_map_.source_to_frame.matrix() == map_to_frame.matrix() && moved_map_.region.contains(box)) {
    return moved_map_.tree;
  }
  moved_map_ = MovedMap();  // the old copy goes before the new one is built
  // Some slack, so the next cloud of a slightly different extent still fits.
  const Eigen::Vector3d slack = Eigen::Vector3d::Constant(kMapMargin);
  const Eigen::AlignedBox3d region(box.min() - slack, box.max() + slack);
  Stopwatch watch;
  auto tree = resampleOccupancy(*map, map_to_frame, region);
  NODELET_INFO("moved the OctoMap into frame '%s' over %.2f x %.2f x %.2f m in %.0f ms", frame.c_str(),
               region.sizes().x(), region.sizes().y(), region.sizes().z(), watch.elapsedMs());
  moved_map_ = MovedMap{map, frame, map_to_frame, region, tree};
  return tree;
}

bool SegmentationNodelet::segmentService(SegmentCloud::Request& request, SegmentCloud::Response& response) {
  if (stopping_) return false;
  handleTimeJump();
  sensor_msgs::PointCloud2ConstPtr cloud;
  const bool use_latest = request.cloud.fields.empty() && request.cloud.data.empty() &&
                          static_cast<std::size_t>(request.cloud.width) * request.cloud.height == 0;
  const double timeout = std::max(0.0, std::isfinite(request.timeout) ? request.timeout : 0.0);
  if (use_latest) {
    {
      std::lock_guard<std::mutex> lock(inputs_mutex_);
      cloud = latest_cloud_;
    }
    if (!cloud && timeout > 0.0) {
      // Continuous mode without output subscribers does not subscribe ~input: do for the wait.
      {
        std::lock_guard<std::mutex> lock(subscription_mutex_);
        ++latest_waiters_;
      }
      updateInputSubscription();
      {
        std::unique_lock<std::mutex> lock(inputs_mutex_);
        cloud_arrived_.wait_for(lock, std::chrono::duration<double>(timeout),
                                [this] { return latest_cloud_ != nullptr || stopping_; });
        cloud = latest_cloud_;
      }
      {
        std::lock_guard<std::mutex> lock(subscription_mutex_);
        --latest_waiters_;
      }
      updateInputSubscription();
    }
    if (!cloud) {
      response.status = timeout > 0.0 ? Response::TIMEOUT : Response::NO_CLOUD;
      response.message = timeout > 0.0 ? "no cloud arrived on ~input within " + std::to_string(timeout) + " s"
                                       : "no cloud received on ~input yet (and none in the request)";
      NODELET_WARN("segment: %s", response.message.c_str());
      return true;
    }
  } else {
    cloud = boost::make_shared<sensor_msgs::PointCloud2>(std::move(request.cloud));  // no copy of a large cloud
  }
  std::optional<AxisAlignedBox> roi;
  if (request.use_roi) {
    roi = AxisAlignedBox{Eigen::Vector3f(request.roi_min.x, request.roi_min.y, request.roi_min.z),
                         Eigen::Vector3f(request.roi_max.x, request.roi_max.y, request.roi_max.z)};
  }
  Outcome outcome = process(*cloud, ros::Duration(std::max(timeout, transform_timeout_)), roi);
  response.status = outcome.status;
  response.message = outcome.message;
  response.objects = std::move(outcome.objects);
  for (const auto& [stage, ms] : outcome.timings) {
    response.timing_stages.push_back(stage);
    response.timing_ms.push_back(ms);
  }
  if (outcome.status != Response::SUCCESS) NODELET_WARN("segment: status %d: %s", outcome.status, outcome.message.c_str());
  return true;  // failures are reported in the response, not as a failed call
}

}  // namespace symmetry_segmentation

PLUGINLIB_EXPORT_CLASS(symmetry_segmentation::SegmentationNodelet, nodelet::Nodelet)
