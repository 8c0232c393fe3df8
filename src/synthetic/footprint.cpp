#include "symmetry_segmentation/synthetic/footprint.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace symmetry_segmentation {
namespace synthetic {
namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

/// Gap between the polygons along the outward normals of `a`'s edges.
double separationAlongEdgesOf(const Footprint& a, const Footprint& b) {
  double best = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Eigen::Vector2d edge = a[(i + 1) % a.size()] - a[i];
    const Eigen::Vector2d normal = Eigen::Vector2d(edge.y(), -edge.x()).normalized();
    double a_max = -std::numeric_limits<double>::infinity();
    for (const auto& p : a) a_max = std::max(a_max, normal.dot(p));
    double b_min = std::numeric_limits<double>::infinity();
    for (const auto& p : b) b_min = std::min(b_min, normal.dot(p));
    best = std::max(best, b_min - a_max);
  }
  return best;
}

}  // namespace

Footprint convexHull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
  });
  if (points.size() < 3) return points;
  Footprint hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

std::vector<Eigen::Vector2d> circumscribedPolygon(double radius, int sides) {
  const double vertex_radius = radius / std::cos(M_PI / sides);
  std::vector<Eigen::Vector2d> polygon;
  for (int i = 0; i < sides; ++i) {
    const double angle = 2.0 * M_PI * (i + 0.5) / sides;
    polygon.emplace_back(vertex_radius * std::cos(angle), vertex_radius * std::sin(angle));
  }
  return polygon;
}

Footprint placeFootprint(const Footprint& footprint, const Eigen::Vector2d& position, double yaw) {
  const Eigen::Rotation2Dd rotation(yaw);
  Footprint placed;
  placed.reserve(footprint.size());
  for (const auto& p : footprint) placed.push_back(rotation * p + position);
  return placed;
}

double separation(const Footprint& a, const Footprint& b) {
  return std::max(separationAlongEdgesOf(a, b), separationAlongEdgesOf(b, a));
}

void footprintBounds(const Footprint& footprint, Eigen::Vector2d& min, Eigen::Vector2d& max) {
  min = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  max = -min;
  for (const auto& p : footprint) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
}

}  // namespace synthetic
}  // namespace symmetry_segmentation
