#include "symmetry_segmentation/ros/cloud_conversion.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include <pcl/common/io.h>
#include <pcl/common/transforms.h>
#include <pcl_conversions/pcl_conversions.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/point_validity.h"

namespace symmetry_segmentation {

bool hasField(const sensor_msgs::PointCloud2& message, const std::string& name) {
  for (const auto& field : message.fields) {
    if (field.name == name) return true;
  }
  return false;
}

Scene sceneFromCloudMessage(const sensor_msgs::PointCloud2& message) {
  const std::string source = "PointCloud2 in frame '" + message.header.frame_id + "'";
  const std::size_t points = static_cast<std::size_t>(message.width) * message.height;
  if (points == 0) throw InputError(source, "cloud is empty");
  if (!hasField(message, "x") || !hasField(message, "y") || !hasField(message, "z")) {
    throw InputError(source, "cloud has no x, y, z fields");
  }
  if (message.point_step == 0 || message.row_step < static_cast<std::size_t>(message.width) * message.point_step ||
      message.data.size() < static_cast<std::size_t>(message.row_step) * message.height) {
    throw InputError(source, "data size does not match width, height, point_step and row_step");
  }
  // PCL copies each field from offset .. offset + size within a point without checking it: a
  // field reaching past point_step reads outside the data (found by fuzzing).
  for (const auto& field : message.fields) {
    const std::uint64_t value_bytes = pcl::getFieldSize(field.datatype);
    if (value_bytes == 0) {
      throw InputError(source, "field '" + field.name + "' has unknown datatype " + std::to_string(field.datatype));
    }
    const std::uint64_t bytes = value_bytes * std::max<std::uint32_t>(field.count, 1);
    if (field.offset + bytes > message.point_step) {
      throw InputError(source, "field '" + field.name + "' (offset " + std::to_string(field.offset) + ", datatype " +
                                   std::to_string(field.datatype) + ", count " + std::to_string(field.count) +
                                   ") does not fit in point_step " + std::to_string(message.point_step));
    }
  }
  Scene scene;
  scene.name = "ros_cloud";
  scene.cloud_path = source;
  scene.has_normals = hasField(message, "normal_x") && hasField(message, "normal_y") && hasField(message, "normal_z");
  scene.has_color = hasField(message, "rgb") || hasField(message, "rgba");
  scene.cloud.reset(new Cloud);
  // Fields the message lacks are left at PCL's defaults (zero normals, black); has_normals
  // tells the core to estimate normals instead.
  pcl::PCLPointCloud2 pcl_message;
  pcl_conversions::toPCL(message, pcl_message);
  pcl::MsgFieldMap field_map;
  pcl::createMapping<PointT>(pcl_message.fields, field_map);
  pcl::fromPCLPointCloud2(pcl_message, *scene.cloud, field_map);
  if (!scene.has_normals) {
    for (auto& p : scene.cloud->points) p.normal_x = p.normal_y = p.normal_z = 0.0f;
  }
  return scene;
}

std::size_t countFinitePoints(const Cloud& cloud) {
  std::size_t count = 0;
  for (const auto& p : cloud.points) {
    if (isUsablePoint(p)) ++count;
  }
  return count;
}

void transformCloud(Cloud& cloud, const Eigen::Isometry3d& transform, bool with_normals) {
  const Eigen::Affine3f affine(transform.matrix().cast<float>());
  if (with_normals) {
    pcl::transformPointCloudWithNormals(cloud, cloud, affine, true);
  } else {
    pcl::transformPointCloud(cloud, cloud, affine, true);
  }
}

void cropToBox(Cloud& cloud, const Eigen::Vector3f& min, const Eigen::Vector3f& max) {
  if (!min.allFinite() || !max.allFinite()) throw InputError("region of interest is not finite");
  if ((min.array() > max.array()).any()) throw InputError("region of interest is empty (min > max on some axis)");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (auto& p : cloud.points) {
    const Eigen::Vector3f xyz(p.x, p.y, p.z);
    if (!xyz.allFinite()) continue;
    if ((xyz.array() < min.array()).any() || (xyz.array() > max.array()).any()) {
      p.x = p.y = p.z = nan;
    }
  }
  cloud.is_dense = false;
}

}  // namespace symmetry_segmentation
