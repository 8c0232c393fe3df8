#include "symmetry_segmentation/ros/result_conversion.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <pcl/common/io.h>
#include <pcl_conversions/pcl_conversions.h>

#include "symmetry_segmentation/object_box.h"
#include "symmetry_segmentation/point_validity.h"
#include "symmetry_segmentation/segmentation_output.h"

namespace symmetry_segmentation {

namespace {

geometry_msgs::Pose poseOf(const Eigen::Vector3f& position, const Eigen::Quaternionf& orientation) {
  geometry_msgs::Pose pose;
  pose.position.x = position.x();
  pose.position.y = position.y();
  pose.position.z = position.z();
  pose.orientation.w = orientation.w();
  pose.orientation.x = orientation.x();
  pose.orientation.y = orientation.y();
  pose.orientation.z = orientation.z();
  return pose;
}

geometry_msgs::Vector3 vectorOf(const Eigen::Vector3f& v) {
  geometry_msgs::Vector3 vector;
  vector.x = v.x();
  vector.y = v.y();
  vector.z = v.z();
  return vector;
}

}  // namespace

SegmentedObjectArray objectsMessage(const Cloud& cloud, const SegmentationResult& result,
                                    const std_msgs::Header& header) {
  SegmentedObjectArray message;
  message.header = header;
  message.objects.reserve(result.segments.size());
  const std::optional<Eigen::Vector3f> up = supportUp(result);
  for (std::size_t i = 0; i < result.segments.size(); ++i) {
    const Segment& segment = result.segments[i];
    SegmentedObject object;
    object.id = static_cast<uint32_t>(i + 1);
    object.indices.assign(segment.indices.begin(), segment.indices.end());
    Cloud points;
    pcl::copyPointCloud(cloud, segment.indices, points);
    pcl::toROSMsg(points, object.cloud);
    object.cloud.header = header;
    if (segment.symmetry) {
      object.has_symmetry_plane = true;
      object.symmetry_plane.coef = {segment.symmetry->normal.x(), segment.symmetry->normal.y(),
                                    segment.symmetry->normal.z(), segment.symmetry->distance};
    }
    // Every method gives its segments their boxes; a result made elsewhere gets them here alike.
    const float noise = result.support ? result.support->noise : 0.0f;
    const ObjectBox box = segment.box ? *segment.box : objectBox(cloud, segment.indices, up, noise);
    object.bounding_box_pose = poseOf(box.center, Eigen::Quaternionf(box.axes));
    object.bounding_box_size = vectorOf(box.size);
    if (segment.completion) {
      const SegmentCompletion& completion = *segment.completion;
      object.has_completion = true;
      object.completion_points = static_cast<uint32_t>(completion.points.size());
      pcl::PointCloud<pcl::PointXYZ> completed;
      completed.reserve(segment.indices.size() + completion.points.size());
      for (int index : segment.indices) {
        if (index >= 0 && static_cast<std::size_t>(index) < cloud.size()) {
          completed.push_back(pcl::PointXYZ(cloud[index].x, cloud[index].y, cloud[index].z));
        }
      }
      for (const Eigen::Vector3f& p : completion.points) completed.push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
      pcl::toROSMsg(completed, object.completed_cloud);
      object.completed_cloud.header = header;
      object.completed_box_pose = poseOf(completion.box.center, Eigen::Quaternionf(completion.box.axes));
      object.completed_box_size = vectorOf(completion.box.size);
      object.symmetry_frame = poseOf(completion.frame_position, completion.frame_orientation);
    }
    if (segment.scores) {
      object.has_scores = true;
      object.occlusion_score = segment.scores->occlusion;
      object.smoothness_score = segment.scores->smoothness;
    }
    message.objects.push_back(std::move(object));
  }
  return message;
}

std::vector<geometry_msgs::TransformStamped> objectFrames(const SegmentedObjectArray& objects) {
  std::vector<geometry_msgs::TransformStamped> frames;
  for (const SegmentedObject& object : objects.objects) {
    if (object.indices.empty()) continue;
    const geometry_msgs::Pose& pose = object.has_completion ? object.symmetry_frame : object.bounding_box_pose;
    geometry_msgs::TransformStamped frame;
    frame.header = objects.header;
    frame.child_frame_id = "object_" + std::to_string(object.id);
    frame.transform.translation.x = pose.position.x;
    frame.transform.translation.y = pose.position.y;
    frame.transform.translation.z = pose.position.z;
    frame.transform.rotation = pose.orientation;
    frames.push_back(frame);
  }
  return frames;
}

void removeClouds(SegmentedObjectArray& objects) {
  for (SegmentedObject& object : objects.objects) {
    const std_msgs::Header header = object.cloud.header;
    object.cloud = sensor_msgs::PointCloud2();
    object.cloud.header = header;
    object.completed_cloud = sensor_msgs::PointCloud2();
    object.completed_cloud.header = header;
  }
}

namespace {

/// Per cloud point: the 1-based segment holding it (the first one wins), 0 for none.
std::vector<uint32_t> pointLabels(const Cloud& cloud, const SegmentationResult& result) {
  std::vector<uint32_t> labels(cloud.size(), 0);
  for (std::size_t s = result.segments.size(); s-- > 0;) {
    for (int index : result.segments[s].indices) {
      if (index >= 0 && static_cast<std::size_t>(index) < labels.size()) labels[index] = static_cast<uint32_t>(s + 1);
    }
  }
  return labels;
}

}  // namespace

sensor_msgs::PointCloud2 labelledCloudMessage(const Cloud& cloud, const SegmentationResult& result,
                                              const std_msgs::Header& header) {
  const pcl::PointCloud<pcl::PointXYZRGB> colored = colorBySegment(cloud, result.segments);
  const std::vector<uint32_t> labels = pointLabels(cloud, result);
  const bool organized = cloud.isOrganized();
  pcl::PointCloud<pcl::PointXYZRGBL> labelled;
  labelled.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!isUsablePoint(cloud[i])) {
      if (!organized) continue;
      pcl::PointXYZRGBL hole;  // the camera saw nothing here: the pixel stays, without a point
      hole.x = hole.y = hole.z = std::numeric_limits<float>::quiet_NaN();
      hole.label = 0;
      labelled.push_back(hole);
      continue;
    }
    pcl::PointXYZRGBL point;
    point.x = cloud[i].x;
    point.y = cloud[i].y;
    point.z = cloud[i].z;
    point.r = colored[i].r;
    point.g = colored[i].g;
    point.b = colored[i].b;
    point.label = labels[i];
    labelled.push_back(point);
  }
  if (organized) {
    labelled.width = cloud.width;
    labelled.height = cloud.height;
    labelled.is_dense = false;
  }
  sensor_msgs::PointCloud2 message;
  pcl::toROSMsg(labelled, message);
  message.header = header;
  return message;
}

std::optional<sensor_msgs::Image> labelImageMessage(const Cloud& cloud, const SegmentationResult& result,
                                                    const std_msgs::Header& header) {
  if (!cloud.isOrganized()) return std::nullopt;
  const std::vector<uint32_t> labels = pointLabels(cloud, result);
  sensor_msgs::Image image;
  image.header = header;
  image.width = cloud.width;
  image.height = cloud.height;
  image.encoding = "mono16";
  image.is_bigendian = 0;
  image.step = 2 * image.width;
  image.data.resize(static_cast<std::size_t>(image.step) * image.height);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const uint16_t label = static_cast<uint16_t>(std::min<uint32_t>(labels[i], 65535u));
    image.data[2 * i] = static_cast<uint8_t>(label & 0xff);  // little endian
    image.data[2 * i + 1] = static_cast<uint8_t>(label >> 8);
  }
  return image;
}

}  // namespace symmetry_segmentation
