#include "symmetry_segmentation/support_polygon.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>
#include <pcl/surface/convex_hull.h>

namespace symmetry_segmentation {
namespace {

using FlatCloud = pcl::PointCloud<pcl::PointXYZ>;

// Directions a corner is pushed out in when the polygon grows: the grown polygon is the hull of
// the pushed copies, within 2 % of the exact rounded offset.
constexpr int kGrowDirections = 16;
// Spans thinner than this (m) are a line, not an area: qhull would fail on them.
constexpr float kMinSpan = 1e-3f;
// A surface seen under a point of the plane (kSeenUnderTop*), within kUnderReach of it across the
// plane, runs on below the plane: that point is where a wall or a chair's back crosses the
// plane, not the table. (A table's own front edge, seen below its top, only takes its outermost
// points: the margin covers them.) Two voxels of the coarse cloud: a chair's back seen from above
// shows its part under the plane a voxel further out than its crossing (seeds 17-20: with one
// voxel, its crossing widened the table's points 3 cm into the chair's back).
constexpr float kUnderReach = 0.03f;

bool spansAnArea(const FlatCloud& points) {
  if (points.size() < 3) return false;
  Eigen::Vector2f mean = Eigen::Vector2f::Zero();
  for (const auto& p : points.points) mean += Eigen::Vector2f(p.x, p.y);
  mean /= static_cast<float>(points.size());
  Eigen::Matrix2f covariance = Eigen::Matrix2f::Zero();
  for (const auto& p : points.points) {
    const Eigen::Vector2f d = Eigen::Vector2f(p.x, p.y) - mean;
    covariance += d * d.transpose();
  }
  covariance /= static_cast<float>(points.size());
  const float smallest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2f>(covariance).eigenvalues()[0];
  return std::sqrt(std::max(smallest, 0.0f)) > kMinSpan;
}

/// The convex hull of `points` (z = 0), counter-clockwise; empty when it fails.
std::vector<Eigen::Vector2f> hull2d(const FlatCloud::Ptr& points) {
  std::vector<Eigen::Vector2f> corners;
  if (!spansAnArea(*points)) return corners;
  pcl::ConvexHull<pcl::PointXYZ> hull;
  hull.setDimension(2);
  hull.setInputCloud(points);
  FlatCloud hull_points;
  std::vector<pcl::Vertices> polygons;
  hull.reconstruct(hull_points, polygons);
  if (polygons.empty()) return corners;
  for (std::uint32_t index : polygons.front().vertices) {
    corners.emplace_back(hull_points[index].x, hull_points[index].y);
  }
  if (corners.size() < 3) return {};
  float twice_area = 0.0f;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector2f& a = corners[i];
    const Eigen::Vector2f& b = corners[(i + 1) % corners.size()];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  if (twice_area < 0.0f) std::reverse(corners.begin(), corners.end());
  return corners;
}

/// Per point of `flat`: whether a point of `under` (same plane coordinates) lies within
/// kUnderReach of it.
std::vector<bool> seenUnder(const FlatCloud::Ptr& flat, const FlatCloud::Ptr& under) {
  std::vector<bool> result(flat->size(), false);
  if (under->empty()) return result;
  pcl::search::KdTree<pcl::PointXYZ> tree;
  tree.setInputCloud(under);
  std::vector<int> found;
  std::vector<float> squared;
  for (std::size_t i = 0; i < flat->size(); ++i) {
    result[i] = tree.radiusSearch(flat->points[i], kUnderReach, found, squared, 1) > 0;
  }
  return result;
}

}  // namespace

std::optional<SupportPolygon> SupportPolygon::fromPlanePoints(const Cloud& cloud, const PlaneCoefficients& plane,
                                                              float on_plane_distance, float connect_distance,
                                                              float margin) {
  const float norm = plane.head<3>().norm();
  if (!(norm > 1e-6f)) return std::nullopt;
  SupportPolygon polygon;
  const Eigen::Vector3f normal = plane.head<3>() / norm;
  polygon.origin_ = -plane[3] / norm * normal;
  polygon.u_ = normal.unitOrthogonal();
  polygon.v_ = normal.cross(polygon.u_);

  auto on_plane = std::make_shared<FlatCloud>();
  auto under_plane = std::make_shared<FlatCloud>();
  for (const auto& p : cloud.points) {
    const Eigen::Vector3f point = p.getVector3fMap();
    if (!point.allFinite()) continue;
    const float height = normal.dot(point) + plane[3] / norm;
    const Eigen::Vector2f flat = polygon.inPlane(point);
    if (std::fabs(height) <= on_plane_distance) on_plane->push_back(pcl::PointXYZ(flat.x(), flat.y(), 0.0f));
    if (height <= -kSeenUnderTopMin && height >= -kSeenUnderTopMax) {
      under_plane->push_back(pcl::PointXYZ(flat.x(), flat.y(), 0.0f));
    }
  }
  if (on_plane->size() < 3) return std::nullopt;

  pcl::EuclideanClusterExtraction<pcl::PointXYZ> clustering;
  clustering.setClusterTolerance(connect_distance);
  clustering.setMinClusterSize(3);
  clustering.setSearchMethod(std::make_shared<pcl::search::KdTree<pcl::PointXYZ>>());
  clustering.setInputCloud(on_plane);
  std::vector<pcl::PointIndices> groups;
  clustering.extract(groups);  // largest first
  if (groups.empty()) return std::nullopt;
  // The strip a wall leaves on the plane joins the table's points (a wall a few centimetres behind
  // the table) and would stretch the polygon along the wall, over whatever stands beside the
  // table. It keeps the group together but gives no extent; the table's own points do.
  const std::vector<bool> crossing = seenUnder(on_plane, under_plane);
  auto table = std::make_shared<FlatCloud>();
  for (int index : groups.front().indices) {
    if (!crossing[index]) table->push_back(on_plane->points[index]);
  }
  if (table->size() < 3) {  // nothing but crossings: the group as it is
    table->clear();
    for (int index : groups.front().indices) table->push_back(on_plane->points[index]);
  }

  polygon.corners_ = hull2d(table);
  if (polygon.corners_.empty()) return std::nullopt;
  polygon.table_corners_ = polygon.corners_;
  if (margin > 0.0f) {
    auto pushed = std::make_shared<FlatCloud>();
    for (const Eigen::Vector2f& corner : polygon.corners_) {
      for (int k = 0; k < kGrowDirections; ++k) {
        const float angle = 2.0f * static_cast<float>(M_PI) * static_cast<float>(k) / kGrowDirections;
        pushed->push_back(pcl::PointXYZ(corner.x() + margin * std::cos(angle), corner.y() + margin * std::sin(angle), 0.0f));
      }
    }
    polygon.corners_ = hull2d(pushed);
    if (polygon.corners_.empty()) return std::nullopt;
  }
  return polygon;
}

Eigen::Vector2f SupportPolygon::inPlane(const Eigen::Vector3f& point) const {
  const Eigen::Vector3f offset = point - origin_;
  return {u_.dot(offset), v_.dot(offset)};
}

bool SupportPolygon::inside(const std::vector<Eigen::Vector2f>& corners, const Eigen::Vector2f& point) {
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector2f edge = corners[(i + 1) % corners.size()] - corners[i];
    const Eigen::Vector2f to_point = point - corners[i];
    if (edge.x() * to_point.y() - edge.y() * to_point.x() < 0.0f) return false;  // right of a CCW edge
  }
  return true;
}

bool SupportPolygon::contains(const Eigen::Vector3f& point) const { return inside(corners_, inPlane(point)); }

bool SupportPolygon::overTable(const Eigen::Vector3f& point) const { return inside(table_corners_, inPlane(point)); }

std::vector<Eigen::Vector3f> SupportPolygon::corners() const {
  std::vector<Eigen::Vector3f> result;
  result.reserve(corners_.size());
  for (const Eigen::Vector2f& c : corners_) result.push_back(origin_ + c.x() * u_ + c.y() * v_);
  return result;
}

}  // namespace symmetry_segmentation
