#pragma once
// Everything between "a cloud message and what the node knows" and "a core Scene": transform
// into the processing frame, region of interest, occupancy source. Failures carry the status
// code the service returns (symmetry_segmentation/SegmentCloud response constants).

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>
#include <sensor_msgs/PointCloud2.h>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

class RequestError : public std::runtime_error {
 public:
  RequestError(uint8_t status, const std::string& message) : std::runtime_error(message), status_(status) {}
  uint8_t status() const { return status_; }

 private:
  uint8_t status_;
};

struct AxisAlignedBox {
  Eigen::Vector3f min;
  Eigen::Vector3f max;
};

struct SceneInputs {
  Eigen::Isometry3d cloud_to_processing = Eigen::Isometry3d::Identity();
  std::shared_ptr<octomap::OcTree> occupancy;    ///< In the processing frame; null when none.
  std::optional<Eigen::Vector3f> sensor_origin;  ///< In the processing frame: ray-cast origin without a map,
                                                 ///< normal / table orientation always.
  std::optional<AxisAlignedBox> region_of_interest;  ///< In the processing frame.
  std::optional<PlaneCoefficients> table_plane;      ///< In the processing frame, unit normal; none: the core estimates it.
  std::optional<Eigen::Vector3f> up;                 ///< Gravity's up in the processing frame, unit; none: unknown.
  /// When there is no `occupancy` in the processing frame but a map in another one: returns
  /// that map moved into the processing frame over the given box (the cloud's usable points,
  /// processing frame, plus kMapMargin). Its InputErrors become INVALID_INPUT.
  std::function<std::shared_ptr<octomap::OcTree>(const Eigen::AlignedBox3d&)> occupancy_for_region;
};

/// Margin (m) around the cloud over which a map from another frame is moved into the processing
/// frame. The data term's dense cache spans dbuf + dmax + 2 cm around the cloud; reflections
/// farther out ask the map directly, and beyond this margin the moved map answers "unknown".
constexpr double kMapMargin = 0.25;

/// The scene the core segments. Throws RequestError with INVALID_INPUT (empty cloud, no x/y/z,
/// bad layout, no finite point, bad region of interest, a map that cannot be moved into the
/// processing frame) or NO_OCCUPANCY (no map and no origin: none given and the cloud is no
/// camera frame whose camera can be fitted to its pixels).
Scene assembleScene(const sensor_msgs::PointCloud2& cloud, const SceneInputs& inputs);

}  // namespace symmetry_segmentation
