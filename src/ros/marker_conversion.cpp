#include "symmetry_segmentation/ros/marker_conversion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <iomanip>
#include <sstream>
#include <string>

#include <Eigen/Geometry>

#include "symmetry_segmentation/point_validity.h"
#include "symmetry_segmentation/segmentation_output.h"

namespace symmetry_segmentation {
namespace {

constexpr double kPlaneThickness = 0.002;  // m
constexpr double kArrowLength = 0.1;       // m
constexpr float kObjectListHeight = 0.2f;  // m above the highest point
constexpr double kSupportLineWidth = 0.005;  // m
constexpr double kCompletionPointSize = 0.006;  // m: the added points lie a working voxel (1 cm) apart

geometry_msgs::Point toPoint(const Eigen::Vector3f& v) {
  geometry_msgs::Point p;
  p.x = v.x();
  p.y = v.y();
  p.z = v.z();
  return p;
}

std_msgs::ColorRGBA rgba(const Eigen::Vector3i& rgb, float alpha) {
  std_msgs::ColorRGBA color;
  color.r = rgb.x() / 255.0f;
  color.g = rgb.y() / 255.0f;
  color.b = rgb.z() / 255.0f;
  color.a = alpha;
  return color;
}

visualization_msgs::Marker baseMarker(const std_msgs::Header& header, const std::string& ns, int id, int type) {
  visualization_msgs::Marker marker;
  marker.header = header;
  marker.ns = ns;
  marker.id = id;
  marker.type = type;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  return marker;
}

std_msgs::ColorRGBA colorOf(std::size_t segment, float alpha) { return rgba(segmentColor(segment), alpha); }

/// What completion added to `segment`, in the colour segments_completed.ply has it.
std_msgs::ColorRGBA addedColorOf(std::size_t segment, float alpha) { return rgba(addedPointColor(segment), alpha); }

visualization_msgs::Marker boxMarker(const std_msgs::Header& header, const std::string& ns, int id,
                                     const ObjectBox& box, const std_msgs::ColorRGBA& color) {
  auto marker = baseMarker(header, ns, id, visualization_msgs::Marker::CUBE);
  marker.pose.position = toPoint(box.center);
  const Eigen::Quaternionf orientation(box.axes);
  marker.pose.orientation.w = orientation.w();
  marker.pose.orientation.x = orientation.x();
  marker.pose.orientation.y = orientation.y();
  marker.pose.orientation.z = orientation.z();
  marker.scale.x = std::max(1e-3f, box.size.x());
  marker.scale.y = std::max(1e-3f, box.size.y());
  marker.scale.z = std::max(1e-3f, box.size.z());
  marker.color = color;
  return marker;
}

}  // namespace

visualization_msgs::MarkerArray symmetryMarkers(const Cloud& cloud, const SegmentationResult& result,
                                                const std_msgs::Header& header) {
  visualization_msgs::MarkerArray markers;
  visualization_msgs::Marker clear;
  clear.header = header;
  clear.action = visualization_msgs::Marker::DELETEALL;
  markers.markers.push_back(clear);

  for (std::size_t s = 0; s < result.segments.size(); ++s) {
    const Segment& segment = result.segments[s];
    const int id = static_cast<int>(s + 1);
    Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
    Eigen::Vector3f top = Eigen::Vector3f::Constant(-std::numeric_limits<float>::max());
    std::size_t count = 0;
    for (int index : segment.indices) {
      if (index < 0 || static_cast<std::size_t>(index) >= cloud.size()) continue;
      const Eigen::Vector3f p = cloud[index].getVector3fMap();
      if (!p.allFinite()) continue;
      centroid += p;
      top = top.cwiseMax(p);
      ++count;
    }
    if (count == 0) continue;
    centroid /= static_cast<float>(count);

    if (segment.symmetry) {
      const Eigen::Vector3f n = segment.symmetry->normal.normalized();
      // In-plane axes u, v; the patch spans the object's points projected onto the plane.
      const Eigen::Vector3f u = n.unitOrthogonal();
      const Eigen::Vector3f v = n.cross(u);
      Eigen::Vector2f low = Eigen::Vector2f::Constant(std::numeric_limits<float>::max());
      Eigen::Vector2f high = -low;
      for (int index : segment.indices) {
        if (index < 0 || static_cast<std::size_t>(index) >= cloud.size()) continue;
        const Eigen::Vector3f p = cloud[index].getVector3fMap();
        if (!p.allFinite()) continue;
        const Eigen::Vector2f q(u.dot(p), v.dot(p));
        low = low.cwiseMin(q);
        high = high.cwiseMax(q);
      }
      const Eigen::Vector2f mid = 0.5f * (low + high);
      const Eigen::Vector3f center = u * mid.x() + v * mid.y() - n * segment.symmetry->distance;
      Eigen::Matrix3f axes;
      axes << n, u, v;  // the cube's x axis is the plane normal
      const Eigen::Quaternionf orientation(axes);

      auto plane = baseMarker(header, "planes", id, visualization_msgs::Marker::CUBE);
      plane.pose.position = toPoint(center);
      plane.pose.orientation.w = orientation.w();
      plane.pose.orientation.x = orientation.x();
      plane.pose.orientation.y = orientation.y();
      plane.pose.orientation.z = orientation.z();
      plane.scale.x = kPlaneThickness;
      plane.scale.y = std::max(1e-3f, high.x() - low.x());
      plane.scale.z = std::max(1e-3f, high.y() - low.y());
      plane.color = colorOf(s, 0.5f);
      markers.markers.push_back(plane);

      auto arrow = baseMarker(header, "normals", id, visualization_msgs::Marker::ARROW);
      arrow.points.push_back(toPoint(center));
      arrow.points.push_back(toPoint(center + n * static_cast<float>(kArrowLength)));
      arrow.scale.x = 0.005;  // shaft diameter
      arrow.scale.y = 0.01;   // head diameter
      arrow.scale.z = 0.02;   // head length
      arrow.color = colorOf(s, 1.0f);
      markers.markers.push_back(arrow);
    }

    if (segment.completion) {
      // The unseen side in a lighter shade, and the box around the completed object.
      auto added = baseMarker(header, "completions", id, visualization_msgs::Marker::POINTS);
      for (const Eigen::Vector3f& p : segment.completion->points) added.points.push_back(toPoint(p));
      added.scale.x = added.scale.y = kCompletionPointSize;
      added.color = addedColorOf(s, 1.0f);
      if (!added.points.empty()) markers.markers.push_back(added);
      markers.markers.push_back(boxMarker(header, "boxes", id, segment.completion->box, addedColorOf(s, 0.25f)));
    } else if (segment.box) {
      markers.markers.push_back(boxMarker(header, "boxes", id, *segment.box, colorOf(s, 0.25f)));
    }

    auto text = baseMarker(header, "ids", id, visualization_msgs::Marker::TEXT_VIEW_FACING);
    text.pose.position = toPoint(Eigen::Vector3f(centroid.x(), centroid.y(), top.z() + 0.03f));
    text.scale.z = 0.03;  // text height
    text.color = colorOf(s, 1.0f);
    text.text = std::to_string(id);
    markers.markers.push_back(text);
  }

  // The table's extent: outside it nothing was segmented.
  if (result.support && result.support->polygon.size() >= 3) {
    auto outline = baseMarker(header, "support", 0, visualization_msgs::Marker::LINE_STRIP);
    for (const Eigen::Vector3f& corner : result.support->polygon) outline.points.push_back(toPoint(corner));
    outline.points.push_back(outline.points.front());
    outline.scale.x = kSupportLineWidth;
    outline.color.r = outline.color.g = outline.color.b = 0.9f;
    outline.color.a = 1.0f;
    markers.markers.push_back(outline);
  }

  // The object list (rviz has no list display): one text, centred above the whole cloud.
  Eigen::AlignedBox3f scene_box;
  for (const auto& p : cloud.points) {
    if (isUsablePoint(p)) scene_box.extend(p.getVector3fMap());
  }
  if (!scene_box.isEmpty()) {
    const Eigen::Vector3f centre = scene_box.center();
    auto list = baseMarker(header, "object_list", 0, visualization_msgs::Marker::TEXT_VIEW_FACING);
    list.pose.position = toPoint(Eigen::Vector3f(centre.x(), centre.y(), scene_box.max().z() + kObjectListHeight));
    list.scale.z = 0.02;  // text height
    list.color.r = list.color.g = list.color.b = list.color.a = 1.0f;
    list.text = objectListText(cloud, result);
    markers.markers.push_back(list);
  }
  return markers;
}

std::string objectListText(const Cloud& cloud, const SegmentationResult& result) {
  std::ostringstream text;
  text << result.segments.size() << (result.segments.size() == 1 ? " object" : " objects");
  text << std::fixed;
  for (std::size_t s = 0; s < result.segments.size(); ++s) {
    const Segment& segment = result.segments[s];
    std::size_t points = 0;
    for (int index : segment.indices) {
      if (index >= 0 && static_cast<std::size_t>(index) < cloud.size() && isUsablePoint(cloud[index])) ++points;
    }
    text << "\n" << (s + 1) << ": " << points << " points";
    if (segment.scores) {
      text << std::setprecision(3) << ", occlusion " << segment.scores->occlusion << ", smoothness "
           << segment.scores->smoothness;
    }
  }
  return text.str();
}

}  // namespace symmetry_segmentation
