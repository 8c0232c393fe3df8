#include "symmetry_segmentation/segmentation_output.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/filesystem.hpp>
#include <pcl/io/ply_io.h>
#include <pcl/io/png_io.h>

#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {

Eigen::Vector3i segmentColor(std::size_t index) {
  // Golden-angle hue steps keep neighbouring segment ids far apart in colour.
  const double hue = std::fmod(index * 137.508, 360.0) / 60.0;
  const double saturation = index % 2 == 0 ? 0.85 : 0.6, value = index % 3 == 2 ? 0.75 : 0.95;
  const double c = value * saturation, x = c * (1 - std::fabs(std::fmod(hue, 2.0) - 1)), m = value - c;
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(hue)) {
    case 0: r = c; g = x; break;
    case 1: r = x; g = c; break;
    case 2: g = c; b = x; break;
    case 3: g = x; b = c; break;
    case 4: r = x; b = c; break;
    default: r = c; b = x; break;
  }
  return Eigen::Vector3i(static_cast<int>((r + m) * 255), static_cast<int>((g + m) * 255),
                         static_cast<int>((b + m) * 255));
}

pcl::PointCloud<pcl::PointXYZRGB> colorBySegment(const Cloud& cloud, const std::vector<Segment>& segments) {
  pcl::PointCloud<pcl::PointXYZRGB> colored;
  colored.resize(cloud.size());
  std::vector<int> owner(cloud.size(), -1);
  for (std::size_t s = 0; s < segments.size(); ++s) {
    for (int index : segments[s].indices) {
      if (index >= 0 && static_cast<std::size_t>(index) < owner.size() && owner[index] < 0) owner[index] = static_cast<int>(s);
    }
  }
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    auto& q = colored.points[i];
    q.x = cloud.points[i].x;
    q.y = cloud.points[i].y;
    q.z = cloud.points[i].z;
    if (owner[i] >= 0) {
      const Eigen::Vector3i color = segmentColor(static_cast<std::size_t>(owner[i]));
      q.r = static_cast<std::uint8_t>(color.x());
      q.g = static_cast<std::uint8_t>(color.y());
      q.b = static_cast<std::uint8_t>(color.z());
    } else {
      q.r = q.g = q.b = 150;
    }
  }
  colored.width = static_cast<std::uint32_t>(colored.size());
  colored.height = 1;
  return colored;
}

namespace {

pcl::PointXYZRGB coloredPoint(const Eigen::Vector3f& p, const Eigen::Vector3i& c) {
  pcl::PointXYZRGB q;
  q.x = p.x();
  q.y = p.y();
  q.z = p.z();
  q.r = static_cast<std::uint8_t>(c.x());
  q.g = static_cast<std::uint8_t>(c.y());
  q.b = static_cast<std::uint8_t>(c.z());
  return q;
}

void addSegmentsAddedPoints(const Segment& segment, std::size_t index, pcl::PointCloud<pcl::PointXYZRGB>& out) {
  if (!segment.completion) return;
  const Eigen::Vector3i shade = addedPointColor(index);
  for (const Eigen::Vector3f& p : segment.completion->points) out.push_back(coloredPoint(p, shade));
}

}  // namespace

Eigen::Vector3i addedPointColor(std::size_t index) {
  return (segmentColor(index) + Eigen::Vector3i::Constant(255)) / 2;
}

pcl::PointCloud<pcl::PointXYZRGB> addedPoints(const std::vector<Segment>& segments) {
  pcl::PointCloud<pcl::PointXYZRGB> added;
  for (std::size_t s = 0; s < segments.size(); ++s) addSegmentsAddedPoints(segments[s], s, added);
  added.width = static_cast<std::uint32_t>(added.size());
  added.height = 1;
  return added;
}

pcl::PointCloud<pcl::PointXYZRGB> completedObjects(const Cloud& cloud, const std::vector<Segment>& segments) {
  pcl::PointCloud<pcl::PointXYZRGB> colored;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const Eigen::Vector3i color = segmentColor(s);
    for (int index : segments[s].indices) {
      if (index >= 0 && static_cast<std::size_t>(index) < cloud.size()) {
        colored.push_back(coloredPoint(cloud.points[index].getVector3fMap(), color));
      }
    }
    addSegmentsAddedPoints(segments[s], s, colored);
  }
  colored.width = static_cast<std::uint32_t>(colored.size());
  colored.height = 1;
  return colored;
}

void writeColoredPly(const pcl::PointCloud<pcl::PointXYZRGB>& cloud, const std::string& path) {
  if (pcl::io::savePLYFileBinary(path, cloud) != 0) throw InputError(path, "cannot write PLY");
}

View defaultView(const Scene& scene, const std::vector<Segment>& segments) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::size_t count = 0;
  auto accumulate = [&](int i) {
    const auto& p = scene.cloud->points[i];
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
      sum += p.getVector3fMap().cast<double>();
      ++count;
    }
  };
  for (const auto& segment : segments) for (int i : segment.indices) accumulate(i);
  if (count == 0) for (std::size_t i = 0; i < scene.size(); ++i) accumulate(static_cast<int>(i));
  View view;
  view.target = count > 0 ? Eigen::Vector3f((sum / static_cast<double>(count)).cast<float>()) : Eigen::Vector3f::Zero();
  Eigen::Vector3f up = scene.table_plane ? Eigen::Vector3f(scene.table_plane->head<3>()) : Eigen::Vector3f(0, -1, 0);
  if (!scene.sensor_origins.empty()) {
    view.eye = scene.sensor_origins.front();
    if (scene.table_plane && up.dot(view.eye - view.target) < 0) up = -up;  // the sensor looks down on the table
  } else {
    if (scene.table_plane && up.dot(view.target) + (*scene.table_plane)[3] < 0) up = -up;
    view.eye = view.target + 0.8f * up + 0.6f * up.unitOrthogonal();
  }
  view.up = up;
  return view;
}

std::vector<int> segmentedPoints(const std::vector<Segment>& segments) {
  std::vector<int> all;
  for (const auto& segment : segments) all.insert(all.end(), segment.indices.begin(), segment.indices.end());
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

void renderPng(const pcl::PointCloud<pcl::PointXYZRGB>& cloud, const View& view, const std::string& path,
               const std::vector<int>& focus, int width, int height) {
  Eigen::Vector3f forward = view.target - view.eye;
  if (forward.norm() < 1e-6f) forward = Eigen::Vector3f::UnitZ();
  forward.normalize();
  Eigen::Vector3f right = forward.cross(view.up);
  if (right.norm() < 1e-6f) right = forward.unitOrthogonal();
  right.normalize();
  const Eigen::Vector3f down = forward.cross(right);

  std::vector<Eigen::Vector3f> camera_points(cloud.size(), Eigen::Vector3f::Constant(-1));
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto& p = cloud.points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    const Eigen::Vector3f d = p.getVector3fMap() - view.eye;
    const Eigen::Vector3f c(d.dot(right), d.dot(down), d.dot(forward));
    if (c.z() > 0.05f) camera_points[i] = c;
  }
  // Fit the focal length so every focus point in front of the camera is in the picture.
  float max_x = 1e-3f, max_y = 1e-3f;
  auto fit = [&](std::size_t i) {
    const Eigen::Vector3f& c = camera_points[i];
    if (c.z() <= 0.0f) return;
    max_x = std::max(max_x, std::fabs(c.x() / c.z()));
    max_y = std::max(max_y, std::fabs(c.y() / c.z()));
  };
  if (focus.empty()) {
    for (std::size_t i = 0; i < cloud.size(); ++i) fit(i);
  } else {
    for (int i : focus) if (i >= 0 && static_cast<std::size_t>(i) < cloud.size()) fit(static_cast<std::size_t>(i));
  }
  const float focal = 0.9f * std::min(0.5f * width / max_x, 0.5f * height / max_y);
  std::vector<float> depth(static_cast<std::size_t>(width) * height, std::numeric_limits<float>::max());
  std::vector<unsigned char> image(depth.size() * 3, 255);
  const float splat_metres = 0.004f;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3f& c = camera_points[i];
    if (c.z() <= 0.0f) continue;
    const int u = static_cast<int>(std::lround(focal * c.x() / c.z() + 0.5f * width));
    const int v = static_cast<int>(std::lround(focal * c.y() / c.z() + 0.5f * height));
    const int radius = std::clamp(static_cast<int>(focal * splat_metres / c.z()), 1, 6);
    for (int dv = -radius; dv <= radius; ++dv) {
      for (int du = -radius; du <= radius; ++du) {
        const int x = u + du, y = v + dv;
        if (x < 0 || y < 0 || x >= width || y >= height) continue;
        const std::size_t pixel = static_cast<std::size_t>(y) * width + x;
        if (c.z() >= depth[pixel]) continue;
        depth[pixel] = c.z();
        image[3 * pixel] = cloud.points[i].r;
        image[3 * pixel + 1] = cloud.points[i].g;
        image[3 * pixel + 2] = cloud.points[i].b;
      }
    }
  }
  // saveRgbPNGFile reports nothing: a missing or empty file is the only sign it failed, so a
  // stale picture from an earlier run must not be there to pass for a new one.
  boost::system::error_code ec;
  if (boost::filesystem::is_regular_file(path, ec)) boost::filesystem::remove(path, ec);
  pcl::io::saveRgbPNGFile(path, image.data(), width, height);
  const auto written = boost::filesystem::file_size(path, ec);
  if (ec || written == 0) throw InputError(path, "cannot write PNG");
}

}  // namespace symmetry_segmentation
