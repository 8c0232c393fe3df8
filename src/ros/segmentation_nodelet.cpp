#include "symmetry_segmentation/ros/segmentation_nodelet.h"

#include <malloc.h>

#include <chrono>
#include <cmath>
#include <set>
#include <sstream>

#include <pcl/console/print.h>
#include <pluginlib/class_list_macros.hpp>
#include <tf2_eigen/tf2_eigen.h>
#include <visualization_msgs/MarkerArray.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/ros/cloud_conversion.h"
#include "symmetry_segmentation/ros/live_sections.h"
#include "symmetry_segmentation/ros/marker_conversion.h"
#include "symmetry_segmentation/ros/octomap_conversion.h"
#include "symmetry_segmentation/ros/parameters.h"
#include "symmetry_segmentation/ros/result_conversion.h"
#include "symmetry_segmentation/ros/table_plane.h"
#include "symmetry_segmentation/segmenter.h"
#include "symmetry_segmentation/stopwatch.h"

namespace symmetry_segmentation {

namespace {
using Response = SegmentCloud::Response;

constexpr double kTimeJumpTolerance = 0.5;  // s: smaller jumps back are not acted on

/// Names in the private namespace the node reads itself; every other name is an algorithm
/// parameter. lazy, verbose_connection, duration_to_warn_no_connection and (in
/// segmentation_node, whose process name is the nodelet's) use_multithread_callback are
/// NodeletLazy's, diagnostic_period diagnostic_updater's.
const std::set<std::string>& interfaceParameterNames() {
  static const std::set<std::string> names = {"mode",
                                              "method",
                                              "fixed_frame",
                                              "sensor_frame",
                                              "up_frame",
                                              "table_plane",
                                              "table_plane_frame",
                                              "transform_timeout",
                                              "service_threads",
                                              "max_input_points",
                                              "max_rate",
                                              "publish_object_frames",
                                              "diagnostic_period",
                                              "lazy",
                                              "verbose_connection",
                                              "duration_to_warn_no_connection",
                                              "use_multithread_callback"};
  return names;
}

std::string statusName(uint8_t status) {
  switch (status) {
    case Response::SUCCESS: return "SUCCESS";
    case Response::NO_CLOUD: return "NO_CLOUD";
    case Response::NO_OCCUPANCY: return "NO_OCCUPANCY";
    case Response::INVALID_INPUT: return "INVALID_INPUT";
    case Response::TIMEOUT: return "TIMEOUT";
    case Response::TRANSFORM_FAILED: return "TRANSFORM_FAILED";
    case Response::SEGMENTATION_FAILED: return "SEGMENTATION_FAILED";
    default: return std::to_string(status);
  }
}

std::string joined(const ConfigValues& values) {
  std::string text;
  for (const auto& [key, value] : values) text += (text.empty() ? "" : ", ") + key + " " + value;
  return text;
}

/// Reads an optional interface parameter of type T; a value of another type is logged and the
/// default kept (ros::NodeHandle::param would keep it silently).
template <class T>
void readParameter(const ros::NodeHandle& handle, const std::string& name, T& value, const char* type) {
  if (!handle.hasParam(name)) return;
  if (!handle.getParam(name, value)) {
    ROS_ERROR_NAMED("SegmentationNodelet", "~%s is not a %s; using the default", name.c_str(), type);
  }
}

// glibc gives threads that allocate at the same time arenas of their own (up to 8 per core:
// here the ~segment threads, the worker, the core's parallelFor and OpenMP threads), and an
// arena keeps what is freed in it for reuse: only free space at its very top goes back to the
// system. So every arena stays at the largest footprint it ever had (in the soak ~45 of the
// ~62 MB in arenas were free; heaptrack found 39 KB leaked), and under load the arenas reach
// their peaks one by one, also after the soak's baseline. Returning the free pages after each
// segmentation makes the resident memory follow the memory in use.
void releaseFreedMemory() { malloc_trim(0); }
}  // namespace

SegmentationNodelet::~SegmentationNodelet() {
  {
    std::lock_guard<std::mutex> lock(inputs_mutex_);  // a waiting ~segment call sees stopping_
    stopping_ = true;
  }
  cloud_arrived_.notify_all();
  // Callbacks may still be running on other threads while members are destroyed (in reverse
  // order of declaration). Stop every source of callbacks first: the worker (its segmentation
  // in progress finishes), the ~segment threads (stopping the spinner joins them), the live
  // parameter servers and the subscribers; the tf listener's thread goes before the buffer.
  if (worker_) worker_->stop();
  diagnostics_timer_.stop();
  service_.shutdown();
  if (service_spinner_) service_spinner_->stop();
  live_sections_.clear();
  interface_server_.reset();
  {
    boost::mutex::scoped_lock lock(connection_mutex_);
    cloud_subscriber_.shutdown();
  }
  octomap_subscriber_.shutdown();
  plane_subscriber_.shutdown();
  tf_listener_.reset();
}

void SegmentationNodelet::loadInterfaceParameters() {
  const ros::NodeHandle& pnh = getPrivateNodeHandle();
  std::string mode = "continuous";
  readParameter(pnh, "mode", mode, "string");
  if (mode != "continuous" && mode != "on_demand") {
    NODELET_ERROR("~mode '%s' is neither 'continuous' nor 'on_demand'; using 'continuous'", mode.c_str());
    mode = "continuous";
  }
  continuous_ = mode == "continuous";
  method_ = defaultMethod();
  readParameter(pnh, "method", method_, "string");
  readParameter(pnh, "fixed_frame", fixed_frame_, "string");
  readParameter(pnh, "sensor_frame", sensor_frame_, "string");
  readParameter(pnh, "up_frame", up_frame_, "string");
  readParameter(pnh, "transform_timeout", transform_timeout_, "number");
  readParameter(pnh, "max_input_points", max_input_points_, "integer");
  readParameter(pnh, "service_threads", service_threads_, "integer");
  readParameter(pnh, "max_rate", max_rate_, "number");
  readParameter(pnh, "publish_object_frames", publish_object_frames_, "bool");
  if (!(transform_timeout_ >= 0.0)) {
    NODELET_ERROR("~transform_timeout %g is not a duration; using 0.1", transform_timeout_);
    transform_timeout_ = 0.1;
  }
  if (service_threads_ < 1) {
    NODELET_ERROR("~service_threads %d is less than 1; using 1", service_threads_);
    service_threads_ = 1;
  }
  if (!(max_rate_ >= 0.0)) {
    NODELET_ERROR("~max_rate %g is not a rate; using 0 (no limit)", max_rate_);
    max_rate_ = 0.0;
  }
  if (max_input_points_ < 0) {
    NODELET_ERROR("~max_input_points %d is negative; using 0 (no limit)", max_input_points_);
    max_input_points_ = 0;
  }

  // ~table_plane: [a, b, c, d] in ~table_plane_frame (default: the processing frame).
  std::string plane_frame;
  readParameter(pnh, "table_plane_frame", plane_frame, "string");
  XmlRpc::XmlRpcValue plane;
  if (pnh.getParam("table_plane", plane)) {
    try {
      if (plane.getType() != XmlRpc::XmlRpcValue::TypeArray) throw InputError("expected a list [a, b, c, d]");
      std::vector<double> values;
      for (int i = 0; i < plane.size(); ++i) {
        if (plane[i].getType() == XmlRpc::XmlRpcValue::TypeInt) {
          values.push_back(static_cast<int>(plane[i]));
        } else if (plane[i].getType() == XmlRpc::XmlRpcValue::TypeDouble) {
          values.push_back(static_cast<double>(plane[i]));
        } else {
          throw InputError("expected numbers [a, b, c, d]");
        }
      }
      if (!values.empty()) plane_parameter_ = GivenPlane{planeFromCoefficients(values), plane_frame, ros::Time(), "parameter"};
    } catch (const InputError& error) {
      NODELET_ERROR("~table_plane: %s; not used (the table is estimated from each cloud)", error.what());
    }
  }
}

void SegmentationNodelet::loadAlgorithmParameters() {
  // Everything in the private namespace at once: the interface parameters are skipped, the rest
  // is one configuration, validated once (a rejected one leaves the defaults in force).
  XmlRpc::XmlRpcValue parameters;
  ros::param::get(getPrivateNodeHandle().getNamespace(), parameters);
  AlgorithmParameters loaded = algorithmParameters(parameters, interfaceParameterNames());
  if (!loaded.problems.empty()) {
    NODELET_ERROR("rejected the algorithm parameters in %s; the defaults are in force. Problems:",
                  getPrivateNodeHandle().getNamespace().c_str());
    for (const auto& problem : loaded.problems) NODELET_ERROR("  %s", problem.c_str());
  } else if (loaded.values > 0) {
    NODELET_INFO("%zu algorithm parameters loaded", loaded.values);
  }
  try {
    makeSegmenter(method_, loaded.config);
  } catch (const std::exception& error) {
    NODELET_ERROR("~method: %s; using method '%s'", error.what(), defaultMethod().c_str());
    method_ = defaultMethod();
  }
  std::lock_guard<std::mutex> lock(config_mutex_);
  config_ = loaded.config;
}

void SegmentationNodelet::startLiveParameters() {
  for (const auto& problem : liveSectionProblems()) NODELET_ERROR("%s", problem.c_str());
  SegmentationConfig in_force;
  {
    std::lock_guard<std::mutex> lock(config_mutex_);
    in_force = config_;
  }
  // One server per section, in the section's namespace: ~symmetry/filter/s_occl is the live
  // name and the start-up name at once. They start from the values in force, not from the .cfg
  // defaults, and write those back to the parameter server.
  for (const auto& type : liveSectionTypes()) {
    try {
      live_sections_.push_back(type.start(ros::NodeHandle(*pnh_, parameterPath(type.section)), reconfigure_mutex_,
                                          in_force, [this](const ConfigValues& requested) {
                                            return applyLiveChange(requested);
                                          }));
    } catch (const std::exception& error) {  // a generated type the schema does not match
      NODELET_ERROR("no live parameters in ~%s: %s", parameterPath(type.section).c_str(), error.what());
    }
  }
  interface_server_ = std::make_unique<dynamic_reconfigure::Server<LiveInterfaceConfig>>(reconfigure_mutex_, *pnh_);
  LiveInterfaceConfig live;
  live.mode = continuous() ? "continuous" : "on_demand";
  interface_server_->updateConfig(live);
  interface_server_->setCallback(
      [this](LiveInterfaceConfig& config, uint32_t level) { reconfigureInterface(config, level); });
}

ConfigValues SegmentationNodelet::applyLiveChange(const ConfigValues& requested) {
  std::lock_guard<std::mutex> lock(config_mutex_);
  try {
    const SegmentationConfig next = configWithValues(config_, requested);
    ConfigValues changed;
    for (const auto& entry : requested) {
      const std::string value = configValueText(next, entry.first);
      if (value != configValueText(config_, entry.first)) changed.emplace_back(entry.first, value);
    }
    if (!changed.empty()) NODELET_INFO("live parameters changed: %s", joined(changed).c_str());
    config_ = next;
  } catch (const InputError& error) {
    // As a whole: none of the requested values is taken, and the servers show what is in force.
    NODELET_ERROR("rejected the live change (%s): %s; the previous values stay in force", joined(requested).c_str(),
                  error.what());
  }
  ConfigValues in_force;
  for (const auto& entry : requested) in_force.emplace_back(entry.first, configValueText(config_, entry.first));
  return in_force;
}

void SegmentationNodelet::reconfigureInterface(LiveInterfaceConfig& live, uint32_t) {
  if (live.mode != "continuous" && live.mode != "on_demand") {
    NODELET_ERROR("reconfigure: mode '%s' is neither 'continuous' nor 'on_demand'; unchanged", live.mode.c_str());
    live.mode = continuous() ? "continuous" : "on_demand";
  }
  const bool continuous = live.mode == "continuous";
  if (continuous != continuous_) NODELET_INFO("mode: %s", live.mode.c_str());
  continuous_ = continuous;
  refreshSubscription();
}

void SegmentationNodelet::onInit() {
  // PCL warns for every field a cloud lacks (e.g. normals): expected here, so errors only.
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  nodelet_topic_tools::NodeletLazy::onInit();  // pnh_, nh_, ~lazy
  loadInterfaceParameters();
  loadAlgorithmParameters();

  tf_buffer_ = std::make_unique<tf2_ros::Buffer>();
  tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_, getNodeHandle());
  if (publish_object_frames_) tf_broadcaster_ = std::make_unique<tf2_ros::TransformBroadcaster>();
  moved_maps_ = std::make_unique<MovedMapCache>(
      [this](const octomap::OcTree& source, const Eigen::Isometry3d& source_to_frame, const Eigen::AlignedBox3d& region) {
        Stopwatch watch;
        auto tree = resampleOccupancy(source, source_to_frame, region);
        NODELET_INFO("moved the OctoMap over %.2f x %.2f x %.2f m in %.0f ms", region.sizes().x(), region.sizes().y(),
                     region.sizes().z(), watch.elapsedMs());
        return tree;
      },
      kMapMargin);
  worker_ = std::make_unique<NewestItemWorker<sensor_msgs::PointCloud2ConstPtr>>(
      [this](sensor_msgs::PointCloud2ConstPtr& cloud) { segmentFromTopic(cloud); });
  if (max_rate_ > 0.0) {
    worker_->setMinPeriod(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(1.0 / max_rate_)));
  }

  // Lazy (NodeletLazy): ~input is subscribed while an output has a subscriber (continuous mode).
  objects_publisher_ = advertise<SegmentedObjectArray>(*pnh_, "objects", 1);
  labelled_publisher_ = advertise<sensor_msgs::PointCloud2>(*pnh_, "segmented_cloud", 1);
  markers_publisher_ = advertise<visualization_msgs::MarkerArray>(*pnh_, "symmetry_markers", 1);
  label_image_publisher_ = advertise<sensor_msgs::Image>(*pnh_, "label_image", 1);
  // The service runs on threads of its own, so long segmentations never block the subscriber
  // callbacks (nor other nodelets of the manager).
  ros::NodeHandle service_nh(*pnh_);
  service_nh.setCallbackQueue(&service_queue_);
  service_ = service_nh.advertiseService("segment", &SegmentationNodelet::segmentService, this);
  service_spinner_ = std::make_unique<ros::AsyncSpinner>(static_cast<uint32_t>(service_threads_), &service_queue_);
  service_spinner_->start();
  octomap_subscriber_ = pnh_->subscribe("octomap", 1, &SegmentationNodelet::octomapCallback, this);
  plane_subscriber_ = pnh_->subscribe("table_plane", 1, &SegmentationNodelet::tablePlaneCallback, this);
  refreshSubscription();
  onInitPostProcess();

  diagnostics_ = std::make_unique<diagnostic_updater::Updater>(getNodeHandle(), getPrivateNodeHandle(), getName());
  diagnostics_->setHardwareID("none");
  diagnostics_->add("segmentation", this, &SegmentationNodelet::diagnose);
  // Wall time: a stopped simulated clock (paused bag) must not stop the diagnostics.
  diagnostics_timer_ = getNodeHandle().createWallTimer(ros::WallDuration(std::max(0.1, diagnostics_->getPeriod())),
                                                       [this](const ros::WallTimerEvent&) { diagnostics_->force_update(); });

  startLiveParameters();  // last: tests wait for its services as "the node is ready"
  NODELET_INFO("symmetry segmentation ready: mode %s, method %s, fixed frame '%s', sensor frame '%s', table plane %s",
               continuous() ? "continuous" : "on_demand", method_.c_str(), fixed_frame_.c_str(), sensor_frame_.c_str(),
               plane_parameter_ ? "from ~table_plane" : "estimated unless published on ~table_plane");
}

bool SegmentationNodelet::hasOutputSubscribers() const {
  return objects_publisher_.getNumSubscribers() > 0 || labelled_publisher_.getNumSubscribers() > 0 ||
         markers_publisher_.getNumSubscribers() > 0 || label_image_publisher_.getNumSubscribers() > 0;
}

bool SegmentationNodelet::inputWanted() const {
  return !continuous() || !lazy_ || latest_waiters_ > 0 || hasOutputSubscribers();
}

void SegmentationNodelet::subscribe() {
  if (stopping_ || cloud_subscriber_) return;
  cloud_subscriber_ = pnh_->subscribe("input", 1, &SegmentationNodelet::cloudCallback, this);
  ever_subscribed_ = true;
  NODELET_DEBUG("subscribed to %s", cloud_subscriber_.getTopic().c_str());
}

void SegmentationNodelet::unsubscribe() {
  if (!cloud_subscriber_ || inputWanted()) return;
  NODELET_DEBUG("unsubscribing from %s: nobody listens", cloud_subscriber_.getTopic().c_str());
  cloud_subscriber_.shutdown();
}

void SegmentationNodelet::refreshSubscription() {
  boost::mutex::scoped_lock lock(connection_mutex_);
  if (stopping_) return;
  if (inputWanted()) {
    subscribe();
    connection_status_ = nodelet_topic_tools::SUBSCRIBED;
  } else {
    unsubscribe();
    connection_status_ = nodelet_topic_tools::NOT_SUBSCRIBED;
  }
}

std::string SegmentationNodelet::processingFrame(const std::string& cloud_frame) const {
  if (!fixed_frame_.empty()) return fixed_frame_;
  std::lock_guard<std::mutex> lock(inputs_mutex_);
  return map_.tree ? map_.frame : cloud_frame;
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
  // A cloud waiting from before the jump is stamped in the new "future": no transform for it.
  worker_->clear();
  moved_maps_->clear();
}

Eigen::Isometry3d SegmentationNodelet::transform(const std::string& target, const std::string& source,
                                                 const ros::Time& stamp, const ros::Duration& timeout,
                                                 const std::string& what) const {
  // Against the wall clock: with use_sim_time a stopped player stops the clock, and tf2's own
  // timeout (in ROS time) would then never expire.
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(std::max(0.0, timeout.toSec()));
  std::string error;
  while (true) {
    error.clear();
    if (tf_buffer_->canTransform(target, source, stamp, &error)) {
      try {
        return tf2::transformToEigen(tf_buffer_->lookupTransform(target, source, stamp));
      } catch (const tf2::TransformException& exception) {
        error = exception.what();  // gone in between (buffer cleared): wait on
      }
    }
    if (ros::WallTime::now() >= deadline || !ros::ok() || stopping_) break;
    ros::WallDuration(0.01).sleep();
  }
  throw RequestError(Response::TRANSFORM_FAILED, "no transform from " + what + " frame '" + source +
                                                     "' to processing frame '" + target + "': " + error);
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
  worker_->push(cloud);
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

void SegmentationNodelet::tablePlaneCallback(const pcl_msgs::ModelCoefficients::ConstPtr& message) {
  handleTimeJump();
  if (message->values.empty()) {
    // Withdrawn: back to ~table_plane (the parameter) or the estimate.
    std::lock_guard<std::mutex> lock(inputs_mutex_);
    if (plane_topic_) NODELET_INFO("table plane withdrawn on ~table_plane");
    plane_topic_.reset();
    return;
  }
  try {
    if (message->header.frame_id.empty()) throw InputError("header.frame_id is empty: the plane's frame is unknown");
    const Eigen::Vector4d plane = planeFromCoefficients(std::vector<double>(message->values.begin(), message->values.end()));
    std::lock_guard<std::mutex> lock(inputs_mutex_);
    plane_topic_ = GivenPlane{plane, message->header.frame_id, message->header.stamp, "topic"};
  } catch (const InputError& error) {
    NODELET_ERROR_THROTTLE(5.0, "ignoring table plane on ~table_plane: %s", error.what());
  }
}

void SegmentationNodelet::segmentFromTopic(sensor_msgs::PointCloud2ConstPtr& cloud) {
  if (!continuous() || !hasOutputSubscribers()) return;
  const Outcome outcome = process(*cloud, ros::Duration(transform_timeout_), std::nullopt);
  if (outcome.status == Response::INVALID_INPUT) {
    NODELET_WARN_THROTTLE(5.0, "cloud not segmented: %s", outcome.message.c_str());
  } else if (outcome.status != Response::SUCCESS) {
    NODELET_ERROR_THROTTLE(5.0, "segmentation failed (%s): %s", statusName(outcome.status).c_str(),
                           outcome.message.c_str());
  }
}

SegmentationNodelet::Outcome SegmentationNodelet::process(const sensor_msgs::PointCloud2& cloud,
                                                          const ros::Duration& timeout,
                                                          const std::optional<AxisAlignedBox>& roi) {
  Outcome outcome;
  Stopwatch total_watch;
  try {
    CloudCheckOptions check;
    check.max_points = static_cast<std::size_t>(max_input_points_);
    const std::string problem = cloudMessageProblem(cloud, check);
    if (!problem.empty()) throw RequestError(Response::INVALID_INPUT, problem);
    const std::string frame = processingFrame(cloud.header.frame_id);
    const ros::Time stamp = cloud.header.stamp;
    SceneInputs inputs;
    inputs.region_of_interest = roi;
    // Every frame goes the same way into the processing frame: transform() at the cloud's stamp
    // (the plane: at its own), waiting up to `timeout`.
    if (frame != cloud.header.frame_id) {
      inputs.cloud_to_processing = transform(frame, cloud.header.frame_id, stamp, timeout, "cloud");
    }
    CachedMap map;
    std::optional<GivenPlane> plane;
    {
      std::lock_guard<std::mutex> lock(inputs_mutex_);
      map = map_;
      plane = plane_topic_ ? plane_topic_ : plane_parameter_;
    }
    if (map.tree && map.frame == frame) {
      inputs.occupancy = map.tree;
    } else if (map.tree) {
      // A map in another frame is moved into the processing frame with the transform at the
      // cloud's stamp (where the world was relative to the processing frame when it was seen).
      const Eigen::Isometry3d map_to_frame = transform(frame, map.frame, stamp, timeout, "the OctoMap's");
      inputs.occupancy_for_region = [this, map, frame, map_to_frame](const Eigen::AlignedBox3d& box) {
        return moved_maps_->get(map.tree, frame, map_to_frame, box);
      };
    }
    if (!sensor_frame_.empty()) {
      inputs.sensor_origin = transform(frame, sensor_frame_, stamp, timeout, "sensor").translation().cast<float>();
    } else if (frame != cloud.header.frame_id) {
      // The cloud's own viewpoint: the origin of the frame it was measured in.
      inputs.sensor_origin = inputs.cloud_to_processing.translation().cast<float>();
    }
    if (!up_frame_.empty()) {
      // Gravity: the up_frame's z axis (base_link, odom or map on a level robot) in the processing frame.
      inputs.up = (transform(frame, up_frame_, stamp, timeout, "up").linear() * Eigen::Vector3d::UnitZ()).cast<float>();
    }
    std::string plane_note = "table plane estimated";
    if (plane) {
      Eigen::Vector4d in_frame = plane->plane;
      if (!plane->frame.empty() && plane->frame != frame) {
        const ros::Time plane_stamp = plane->stamp.isZero() ? stamp : plane->stamp;
        in_frame = transformPlane(plane->plane, transform(frame, plane->frame, plane_stamp, timeout, "the table plane's"));
      }
      inputs.table_plane = toPlaneCoefficients(in_frame);
      plane_note = "table plane from ~table_plane (" + plane->source + ")";
    }
    const Scene scene = assembleScene(cloud, inputs);
    const double prepare_ms = total_watch.elapsedMs();

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
    if (tf_broadcaster_) {
      // The same cloud segmented again (~segment on the cached cloud) would send frames with a
      // stamp tf already has, which listeners warn about.
      std::lock_guard<std::mutex> lock(frames_mutex_);
      if (outcome.objects.header.stamp != last_frames_stamp_) {
        tf_broadcaster_->sendTransform(objectFrames(outcome.objects));
        last_frames_stamp_ = outcome.objects.header.stamp;
      }
    }
    if (labelled_publisher_.getNumSubscribers() > 0) {
      labelled_publisher_.publish(labelledCloudMessage(*scene.cloud, result, header));
    }
    if (markers_publisher_.getNumSubscribers() > 0) {
      markers_publisher_.publish(symmetryMarkers(*scene.cloud, result, header));
    }
    if (label_image_publisher_.getNumSubscribers() > 0) {
      // In the camera's own frame and stamp: the image lines up with the camera's image.
      if (auto image = labelImageMessage(*scene.cloud, result, cloud.header)) label_image_publisher_.publish(*image);
    }
    outcome.timings.emplace_back("prepare", prepare_ms);
    for (const auto& stage : result.timing_ms) {
      if (stage.first != "total") outcome.timings.push_back(stage);
    }
    outcome.timings.emplace_back("publish", publish_watch.elapsedMs());
    outcome.timings.emplace_back("total", total_watch.elapsedMs());
    outcome.message = std::to_string(result.segments.size()) + " objects from " + std::to_string(scene.size()) +
                      " points in frame '" + frame + "', " + plane_note;
  } catch (const RequestError& error) {
    outcome.status = error.status();
    outcome.message = error.what();
  } catch (const std::exception& error) {
    outcome.status = Response::SEGMENTATION_FAILED;
    outcome.message = error.what();
  }
  record(outcome, total_watch.elapsedMs());
  releaseFreedMemory();  // the scene, the result and the core's buffers are gone by now
  return outcome;
}

void SegmentationNodelet::record(const Outcome& outcome, double duration_ms) {
  std::lock_guard<std::mutex> lock(statistics_mutex_);
  if (outcome.status == Response::SUCCESS) {
    ++statistics_.segmented;
  } else {
    ++statistics_.failed;
  }
  statistics_.any = true;
  statistics_.last_duration_ms = duration_ms;
  statistics_.last_status = outcome.status;
  statistics_.last_message = outcome.message;
}

void SegmentationNodelet::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  bool subscribed = false;
  {
    boost::mutex::scoped_lock lock(connection_mutex_);
    subscribed = cloud_subscriber_;
  }
  const std::size_t dropped = worker_ ? worker_->dropped() : 0;
  std::lock_guard<std::mutex> lock(statistics_mutex_);
  Statistics& s = statistics_;
  const ros::WallTime now = ros::WallTime::now();
  const double elapsed = s.last_report.isZero() ? 0.0 : (now - s.last_report).toSec();
  const double rate = elapsed > 0.0 ? static_cast<double>(s.segmented - s.segmented_at_last_report) / elapsed : 0.0;
  s.last_report = now;
  s.segmented_at_last_report = s.segmented;
  if (!s.any) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "no segmentation yet");
  } else if (s.last_status == Response::SUCCESS) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, s.last_message);
  } else {
    status.summaryf(diagnostic_msgs::DiagnosticStatus::WARN, "last segmentation failed (%s): %s",
                    statusName(s.last_status).c_str(), s.last_message.c_str());
  }
  status.add("mode", continuous() ? "continuous" : "on_demand");
  status.add("method", method_);
  status.add("input subscribed", subscribed);
  status.addf("segmentation rate (Hz)", "%.3f", rate);
  status.add("segmented clouds", s.segmented);
  status.add("failed segmentations", s.failed);
  status.addf("last duration (ms)", "%.1f", s.last_duration_ms);
  status.add("last status", s.any ? statusName(s.last_status) : std::string("none"));
  status.add("dropped clouds", dropped);
  status.addf("max rate (Hz, 0: none)", "%g", max_rate_);
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
      ++latest_waiters_;
      refreshSubscription();
      {
        std::unique_lock<std::mutex> lock(inputs_mutex_);
        cloud_arrived_.wait_for(lock, std::chrono::duration<double>(timeout),
                                [this] { return latest_cloud_ != nullptr || stopping_; });
        cloud = latest_cloud_;
      }
      --latest_waiters_;
      refreshSubscription();
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
  if (request.without_clouds) removeClouds(response.objects);
  for (const auto& [stage, ms] : outcome.timings) {
    response.timing_stages.push_back(stage);
    response.timing_ms.push_back(ms);
  }
  if (outcome.status != Response::SUCCESS) NODELET_WARN("segment: status %d: %s", outcome.status, outcome.message.c_str());
  return true;  // failures are reported in the response, not as a failed call
}

}  // namespace symmetry_segmentation

PLUGINLIB_EXPORT_CLASS(symmetry_segmentation::SegmentationNodelet, nodelet::Nodelet)
