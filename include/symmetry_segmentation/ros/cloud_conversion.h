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

/// A scene holding the message's points in message order (indices into the message stay valid),
/// with has_normals / has_color from its fields. Throws InputError when the message has no
/// points, no x/y/z fields, or a data size that does not match its layout.
Scene sceneFromCloudMessage(const sensor_msgs::PointCloud2& message);

/// Points the pipeline can use (isUsablePoint: finite, within 100 km).
std::size_t countFinitePoints(const Cloud& cloud);

/// Applies a rigid transform to points (and normals when `with_normals`).
void transformCloud(Cloud& cloud, const Eigen::Isometry3d& transform, bool with_normals);

/// Points outside the axis-aligned box [min, max] become NaN (they keep their index).
/// Throws InputError when the box is empty (min > max on some axis) or not finite.
void cropToBox(Cloud& cloud, const Eigen::Vector3f& min, const Eigen::Vector3f& max);

}  // namespace symmetry_segmentation
