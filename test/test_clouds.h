#pragma once
// Small hand-built clouds with known geometry for unit tests.

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/table_surface.h"

namespace test_clouds {

/// The fitted top of a 1 m x 0.8 m table that rises by `bend` * x^2 over its plane z = 0 (a far
/// table bending away), from its points 5 mm apart (2 cm cells, a 4 cm band).
inline std::optional<symmetry_segmentation::TableSurface> bendingTableTop(float bend) {
  symmetry_segmentation::Cloud table;
  std::vector<int> indices;
  for (float x = -0.5f; x <= 0.5f; x += 0.005f) {
    for (float y = -0.4f; y <= 0.4f; y += 0.005f) {
      symmetry_segmentation::PointT p;
      p.x = x; p.y = y; p.z = bend * x * x;
      indices.push_back(static_cast<int>(table.size()));
      table.push_back(p);
    }
  }
  return symmetry_segmentation::TableSurface::fit(table, indices, symmetry_segmentation::PlaneCoefficients(0, 0, 1, 0),
                                                  0.04f, /*facing_up=*/false, 0.02f);
}

/// Points on the visible faces (top and four sides) of an axis-aligned box standing on z = 0,
/// with outward normals, on a grid of `spacing`.
inline void addBox(symmetry_segmentation::Cloud& cloud, const Eigen::Vector3f& min_corner,
                   const Eigen::Vector3f& size, float spacing) {
  auto add = [&](const Eigen::Vector3f& p, const Eigen::Vector3f& n) {
    symmetry_segmentation::PointT q;
    q.x = p.x(); q.y = p.y(); q.z = p.z();
    q.normal_x = n.x(); q.normal_y = n.y(); q.normal_z = n.z();
    q.r = q.g = q.b = 200;
    cloud.push_back(q);
  };
  const Eigen::Vector3f max_corner = min_corner + size;
  for (float a = min_corner.x(); a <= max_corner.x() + 1e-6f; a += spacing) {
    for (float b = min_corner.y(); b <= max_corner.y() + 1e-6f; b += spacing) {
      add({a, b, max_corner.z()}, Eigen::Vector3f::UnitZ());
    }
  }
  for (float z = min_corner.z() + spacing; z < max_corner.z() - 1e-6f; z += spacing) {
    for (float a = min_corner.x(); a <= max_corner.x() + 1e-6f; a += spacing) {
      add({a, min_corner.y(), z}, -Eigen::Vector3f::UnitY());
      add({a, max_corner.y(), z}, Eigen::Vector3f::UnitY());
    }
    for (float b = min_corner.y() + spacing; b < max_corner.y() - 1e-6f; b += spacing) {
      add({min_corner.x(), b, z}, -Eigen::Vector3f::UnitX());
      add({max_corner.x(), b, z}, Eigen::Vector3f::UnitX());
    }
  }
}

/// A square patch of the plane z = 0 centred on the origin.
inline void addTable(symmetry_segmentation::Cloud& cloud, float half_extent, float spacing) {
  for (float x = -half_extent; x <= half_extent + 1e-6f; x += spacing) {
    for (float y = -half_extent; y <= half_extent + 1e-6f; y += spacing) {
      symmetry_segmentation::PointT q;
      q.x = x; q.y = y; q.z = 0.0f;
      q.normal_x = 0; q.normal_y = 0; q.normal_z = 1;
      q.r = q.g = q.b = 120;
      cloud.push_back(q);
    }
  }
}

/// A wall in the plane y = `y`, facing -y (toward a sensor in front of it): x in
/// [-half_width, half_width], z in [z_min, z_max].
inline void addWall(symmetry_segmentation::Cloud& cloud, float y, float half_width, float z_min, float z_max,
                    float spacing) {
  for (float x = -half_width; x <= half_width + 1e-6f; x += spacing) {
    for (float z = z_min; z <= z_max + 1e-6f; z += spacing) {
      symmetry_segmentation::PointT q;
      q.x = x; q.y = y; q.z = z;
      q.normal_x = 0; q.normal_y = -1; q.normal_z = 0;
      q.r = q.g = q.b = 180;
      cloud.push_back(q);
    }
  }
}

/// Whether the segment from `from` to `to` passes through `box` (slab test): a point seen from
/// `from` is hidden by the box.
inline bool segmentCrossesBox(const Eigen::Vector3f& from, const Eigen::Vector3f& to, const Eigen::AlignedBox3f& box) {
  const Eigen::Vector3f step = to - from;
  float enter = 0.0f, leave = 1.0f;
  for (int d = 0; d < 3; ++d) {
    if (std::fabs(step[d]) < 1e-9f) {
      if (from[d] < box.min()[d] || from[d] > box.max()[d]) return false;
      continue;
    }
    float t0 = (box.min()[d] - from[d]) / step[d], t1 = (box.max()[d] - from[d]) / step[d];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter < leave;
}

/// One view of a box 30 cm long behind a post 6 cm wide, from a sensor in front: only what faces
/// the sensor and no other box hides (labels: 1 the long box, 2 the post, 0 the table).
inline symmetry_segmentation::Scene boxBehindAPost() {
  const Eigen::Vector3f sensor(0.0f, -0.8f, 0.15f);
  const std::vector<Eigen::AlignedBox3f> boxes = {
      {Eigen::Vector3f(-0.15f, 0.10f, 0.0f), Eigen::Vector3f(0.15f, 0.18f, 0.08f)},
      {Eigen::Vector3f(-0.03f, -0.06f, 0.0f), Eigen::Vector3f(0.03f, -0.02f, 0.16f)}};
  const auto hidden = [&](const Eigen::Vector3f& point, int own) {
    for (int b = 0; b < static_cast<int>(boxes.size()); ++b) {
      if (b != own && segmentCrossesBox(sensor, point, boxes[b])) return true;
    }
    return false;
  };
  symmetry_segmentation::Scene scene;
  scene.name = "box_behind_a_post";
  scene.cloud.reset(new symmetry_segmentation::Cloud);
  scene.has_normals = true;
  scene.has_color = true;
  scene.sensor_origins = {sensor};
  scene.table_plane = symmetry_segmentation::PlaneCoefficients(0.0f, 0.0f, 1.0f, 0.0f);
  const auto keepVisible = [&](const symmetry_segmentation::Cloud& part, int own, int label) {
    for (const auto& point : part) {
      const Eigen::Vector3f p = point.getVector3fMap();
      if (point.getNormalVector3fMap().dot(sensor - p) <= 0.0f || hidden(p, own)) continue;
      scene.cloud->push_back(point);
      scene.labels.push_back(label);
    }
  };
  for (int b = 0; b < 2; ++b) {
    symmetry_segmentation::Cloud part;
    test_clouds::addBox(part, boxes[b].min(), boxes[b].sizes(), 0.005f);
    keepVisible(part, b, b + 1);
  }
  symmetry_segmentation::Cloud table;
  test_clouds::addTable(table, 0.6f, 0.005f);
  keepVisible(table, -1, 0);
  return scene;
}


}  // namespace test_clouds
