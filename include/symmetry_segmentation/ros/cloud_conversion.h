#pragma once
// sensor_msgs/PointCloud2 -> the core library's cloud, and the cloud-level steps the node
// applies before segmenting (transform into the processing frame, region of interest).

#include <cstddef>

#include <Eigen/Geometry>
#include <sensor_msgs/PointCloud2.h>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

/// True when the message has a field of that name.
bool hasField(const sensor_msgs::PointCloud2& message, const std::string& name);

struct CloudCheckOptions {
  bool require_frame = true;    ///< An empty header.frame_id is a problem.
  std::size_t max_points = 0;   ///< More than this many points (width x height) is a problem; 0: no limit.
};

/// Why `message` cannot be read as a cloud, in one sentence naming the problem, or "" when it
/// can: empty frame id (when required), no points, too many points, big-endian data, a layout
/// whose sizes disagree (point_step 0, row_step < width x point_step, data size != height x
/// row_step, a field ending beyond point_step, an unknown field datatype), or x/y/z fields that
/// are missing or not single FLOAT32 values. Reads no point data: cheap for any size.
std::string cloudMessageProblem(const sensor_msgs::PointCloud2& message, const CloudCheckOptions& options = {});

/// A scene holding the message's points in message order (indices into the message stay valid),
/// with has_normals / has_color from its fields. Throws InputError when cloudMessageProblem
/// (frame id not required) finds one.
Scene sceneFromCloudMessage(const sensor_msgs::PointCloud2& message);

/// Applies a rigid transform to points (and normals when `with_normals`).
void transformCloud(Cloud& cloud, const Eigen::Isometry3d& transform, bool with_normals);

/// The region of interest [min, max] as a box for Scene::region_of_interest.
/// Throws InputError when the box is empty (min > max on some axis) or not finite.
Eigen::AlignedBox3f regionOfInterest(const Eigen::Vector3f& min, const Eigen::Vector3f& max);

}  // namespace symmetry_segmentation
