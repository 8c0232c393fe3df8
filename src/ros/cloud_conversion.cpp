#include "symmetry_segmentation/ros/cloud_conversion.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

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

namespace {

// Bytes per value of a sensor_msgs/PointField datatype; 0 for an unknown datatype.
std::size_t datatypeSize(uint8_t datatype) {
  switch (datatype) {
    case sensor_msgs::PointField::INT8:
    case sensor_msgs::PointField::UINT8: return 1;
    case sensor_msgs::PointField::INT16:
    case sensor_msgs::PointField::UINT16: return 2;
    case sensor_msgs::PointField::INT32:
    case sensor_msgs::PointField::UINT32:
    case sensor_msgs::PointField::FLOAT32: return 4;
    case sensor_msgs::PointField::FLOAT64: return 8;
    default: return 0;
  }
}

}  // namespace

std::string cloudMessageProblem(const sensor_msgs::PointCloud2& message, const CloudCheckOptions& options) {
  if (options.require_frame && message.header.frame_id.empty()) {
    return "header.frame_id is empty: the cloud's frame is unknown";
  }
  const uint64_t width = message.width, height = message.height;
  const uint64_t points = width * height;
  if (points == 0) {
    return "cloud is empty (width " + std::to_string(width) + " x height " + std::to_string(height) + " = 0 points)";
  }
  if (options.max_points > 0 && points > options.max_points) {
    return "cloud has " + std::to_string(points) + " points, more than the limit of " +
           std::to_string(options.max_points) + " (max_input_points)";
  }
  if (message.is_bigendian) return "big-endian point data is not supported";
  if (message.point_step == 0) return "point_step is 0";
  if (message.row_step < width * message.point_step) {
    return "row_step " + std::to_string(message.row_step) + " is smaller than width " + std::to_string(width) +
           " x point_step " + std::to_string(message.point_step);
  }
  if (message.data.size() != height * message.row_step) {
    return "data holds " + std::to_string(message.data.size()) + " bytes, but height " + std::to_string(height) +
           " x row_step " + std::to_string(message.row_step) + " = " + std::to_string(height * message.row_step);
  }
  for (const auto& field : message.fields) {
    const std::size_t size = datatypeSize(field.datatype);
    if (size == 0) {
      return "field '" + field.name + "' has unknown datatype " + std::to_string(field.datatype);
    }
    const uint64_t end = static_cast<uint64_t>(field.offset) + size * std::max<uint64_t>(field.count, 1);
    if (end > message.point_step) {
      return "field '" + field.name + "' (offset " + std::to_string(field.offset) + ", " +
             std::to_string(end - field.offset) + " bytes) ends beyond point_step " +
             std::to_string(message.point_step);
    }
  }
  for (const char* name : {"x", "y", "z"}) {
    const sensor_msgs::PointField* found = nullptr;
    for (const auto& field : message.fields) {
      if (field.name == name) found = &field;
    }
    if (!found) return std::string("cloud has no '") + name + "' field (x, y and z are required)";
    if (found->datatype != sensor_msgs::PointField::FLOAT32) {
      return std::string("field '") + name + "' has datatype " + std::to_string(found->datatype) +
             "; x, y and z must be FLOAT32 (7)";
    }
    if (found->count != 1) {
      return std::string("field '") + name + "' has count " + std::to_string(found->count) + "; x, y and z must have count 1";
    }
  }
  return "";
}

Scene sceneFromCloudMessage(const sensor_msgs::PointCloud2& message) {
  const std::string source = "PointCloud2 in frame '" + message.header.frame_id + "'";
  CloudCheckOptions layout_only;
  layout_only.require_frame = false;
  const std::string problem = cloudMessageProblem(message, layout_only);
  if (!problem.empty()) throw InputError(source, problem);
  Scene scene;
  scene.name = "ros_cloud";
  scene.cloud_path = source;
  // Normals PCL cannot map (another datatype) would read as zero: estimate them instead.
  const auto float_field = [&message](const std::string& name) {
    for (const auto& field : message.fields) {
      if (field.name == name) return field.datatype == sensor_msgs::PointField::FLOAT32 && field.count == 1;
    }
    return false;
  };
  scene.has_normals = float_field("normal_x") && float_field("normal_y") && float_field("normal_z");
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

void transformCloud(Cloud& cloud, const Eigen::Isometry3d& transform, bool with_normals) {
  const Eigen::Affine3f affine(transform.matrix().cast<float>());
  if (with_normals) {
    pcl::transformPointCloudWithNormals(cloud, cloud, affine, true);
  } else {
    pcl::transformPointCloud(cloud, cloud, affine, true);
  }
}

Eigen::AlignedBox3f regionOfInterest(const Eigen::Vector3f& min, const Eigen::Vector3f& max) {
  if (!min.allFinite() || !max.allFinite()) throw InputError("region of interest is not finite");
  if ((min.array() > max.array()).any()) throw InputError("region of interest is empty (min > max on some axis)");
  return Eigen::AlignedBox3f(min, max);
}

}  // namespace symmetry_segmentation
