// Gravity-aligned object boxes (see the header for why).
#include "symmetry_segmentation/object_box.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include <Eigen/Eigenvalues>

#include "symmetry_segmentation/point_validity.h"
#include "symmetry_segmentation/sparse_cells.h"
#include "symmetry_segmentation/voxel_grid.h"

namespace symmetry_segmentation {
namespace {

// A camera's depth noise spreads a face's points to either side of it: the outermost of them
// make every box too large (a 1.8 cm board 3.3 cm thick on a RealSense view). Each box end is
// pulled in to the quantile leaving this share of the points outside it, by at most
// kNoisePullSigmas times the sensor's noise - so that a real extreme (a cone's tip, a handle)
// loses no more than the noise would have added.
constexpr float kNoisyEndShare = 0.01f;
constexpr float kNoisePullSigmas = 2.0f;

std::vector<Eigen::Vector3f> usablePoints(const Cloud& cloud, const std::vector<int>& indices) {
  std::vector<Eigen::Vector3f> points;
  points.reserve(indices.size());
  for (int index : indices) {
    if (index < 0 || static_cast<std::size_t>(index) >= cloud.size() || !isUsablePoint(cloud[index])) continue;
    points.push_back(cloud[index].getVector3fMap());
  }
  return points;
}

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

/// Convex hull, counter-clockwise (Andrew's monotone chain); all points when fewer than three.
std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> points) {  // a copy: sorted here
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (const auto& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

struct Rectangle {
  Eigen::Vector2d side;  ///< Unit direction of one side; the other is its normal.
  Eigen::Vector2d low, high;  ///< Extents along side and its normal.
  double area() const { return (high - low).prod(); }
};

Rectangle rectangleAlong(const Eigen::Vector2d& side, const std::vector<Eigen::Vector2d>& points) {
  const Eigen::Vector2d normal(-side.y(), side.x());
  Rectangle rectangle{side, Eigen::Vector2d::Constant(std::numeric_limits<double>::max()),
                      Eigen::Vector2d::Constant(std::numeric_limits<double>::lowest())};
  for (const auto& q : points) {
    const Eigen::Vector2d local(side.dot(q), normal.dot(q));
    rectangle.low = rectangle.low.cwiseMin(local);
    rectangle.high = rectangle.high.cwiseMax(local);
  }
  return rectangle;
}

/// How many of `points` lie on the rectangle's sides (within a tenth of its shorter side).
std::size_t pointsOnSides(const Rectangle& rectangle, const std::vector<Eigen::Vector2d>& points) {
  const Eigen::Vector2d normal(-rectangle.side.y(), rectangle.side.x());
  const double reach = 0.1 * (rectangle.high - rectangle.low).minCoeff();
  std::size_t count = 0;
  for (const auto& q : points) {
    const Eigen::Vector2d local(rectangle.side.dot(q), normal.dot(q));
    const Eigen::Vector2d to_side = (local - rectangle.low).cwiseMin(rectangle.high - local);
    if (to_side.minCoeff() <= reach) ++count;
  }
  return count;
}

/// The rectangle around the footprint `points` (convex hull `hull`) to stand the box on: one side
/// lies on a hull edge, as for the smallest rectangle. An object seen from one side shows an L or
/// a single face, for which rectangles of several directions are about as small (a right
/// triangle's hull fits its legs and its hypotenuse with the same area); of those within 15 % of
/// the smallest area, the one whose sides most points lie on wins - visible faces are box sides.
Rectangle footprintRectangle(const std::vector<Eigen::Vector2d>& hull, const std::vector<Eigen::Vector2d>& points) {
  std::vector<Rectangle> rectangles;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d edge = hull[(i + 1) % hull.size()] - hull[i];
    if (edge.norm() > 0.0) rectangles.push_back(rectangleAlong(edge.normalized(), hull));
  }
  if (rectangles.empty()) return rectangleAlong(Eigen::Vector2d::UnitX(), hull);
  double smallest = std::numeric_limits<double>::max();
  for (const auto& rectangle : rectangles) smallest = std::min(smallest, rectangle.area());
  const Rectangle* best = nullptr;
  std::size_t best_on_sides = 0;
  for (const auto& rectangle : rectangles) {
    if (rectangle.area() > 1.15 * smallest) continue;
    const std::size_t on_sides = pointsOnSides(rectangle, points);
    if (!best || on_sides > best_on_sides || (on_sides == best_on_sides && rectangle.area() < best->area())) {
      best = &rectangle;
      best_on_sides = on_sides;
    }
  }
  return *best;
}

/// The box of `points` along the unit columns of `axes` (any order, right-handed), each end pulled
/// in to the kNoisyEndShare quantile of the points along its axis, by at most `max_pull`.
ObjectBox boxAlong(const std::vector<Eigen::Vector3f>& points, const Eigen::Matrix3f& axes, float max_pull) {
  Eigen::Vector3f low = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector3f high = -low;
  for (const auto& p : points) {
    const Eigen::Vector3f local = axes.transpose() * p;
    low = low.cwiseMin(local);
    high = high.cwiseMax(local);
  }
  if (max_pull > 0.0f) {
    std::vector<float> along(points.size());
    for (int k = 0; k < 3; ++k) {
      for (std::size_t i = 0; i < points.size(); ++i) along[i] = axes.col(k).dot(points[i]);
      // The same number of points beyond either end, so that neither end is favoured.
      const auto outside = static_cast<std::ptrdiff_t>(kNoisyEndShare * static_cast<float>(along.size() - 1));
      std::nth_element(along.begin(), along.begin() + outside, along.end());
      const float share_low = along[static_cast<std::size_t>(outside)];
      const auto top = along.end() - 1 - outside;
      std::nth_element(along.begin(), top, along.end());
      low[k] = std::min(share_low, low[k] + max_pull);
      high[k] = std::max(*top, high[k] - max_pull);
    }
  }
  ObjectBox box;
  box.axes = axes;
  box.center = axes * (0.5f * (low + high));
  box.size = high - low;
  return box;
}

/// x's sign is arbitrary; fixed so that its largest component is positive, for stable output.
Eigen::Vector3f withPositiveLargestComponent(const Eigen::Vector3f& axis) {
  Eigen::Index largest = 0;
  axis.cwiseAbs().maxCoeff(&largest);
  return axis[largest] < 0.0f ? Eigen::Vector3f(-axis) : axis;
}

ObjectBox gravityAlignedBox(const std::vector<Eigen::Vector3f>& points, const Eigen::Vector3f& up, float max_pull) {
  const Eigen::Vector3f e1 = up.unitOrthogonal();
  const Eigen::Vector3f e2 = up.cross(e1);
  std::vector<Eigen::Vector2d> footprint;
  footprint.reserve(points.size());
  for (const auto& p : points) footprint.emplace_back(e1.dot(p), e2.dot(p));
  const Eigen::Vector2d side = footprintRectangle(convexHull(footprint), footprint).side;
  Eigen::Matrix3f axes;
  axes.col(0) = withPositiveLargestComponent((static_cast<float>(side.x()) * e1 + static_cast<float>(side.y()) * e2).normalized());
  axes.col(2) = up;
  axes.col(1) = up.cross(axes.col(0));
  ObjectBox box = boxAlong(points, axes, max_pull);
  if (box.size.y() > box.size.x()) {  // x the longer side: turn the footprint by 90 degrees
    axes.col(0) = withPositiveLargestComponent(axes.col(1));
    axes.col(1) = up.cross(axes.col(0));
    box = boxAlong(points, axes, max_pull);
  }
  return box;
}

ObjectBox principalBox(const std::vector<Eigen::Vector3f>& points, float max_pull) {
  Eigen::Vector3f mean = Eigen::Vector3f::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<float>(points.size());
  Eigen::Matrix3f covariance = Eigen::Matrix3f::Zero();
  for (const auto& p : points) covariance += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> solver(covariance);
  Eigen::Matrix3f axes = solver.eigenvectors();
  if (!axes.allFinite()) axes = Eigen::Matrix3f::Identity();
  const ObjectBox unordered = boxAlong(points, axes, 0.0f);
  std::array<int, 3> order = {0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int a, int b) { return unordered.size[a] > unordered.size[b]; });
  Eigen::Matrix3f ordered;
  ordered.col(0) = withPositiveLargestComponent(axes.col(order[0]));
  ordered.col(1) = axes.col(order[1]);
  ordered.col(2) = ordered.col(0).cross(ordered.col(1));
  return boxAlong(points, ordered, max_pull);
}

}  // namespace

ObjectBox objectBox(const Cloud& cloud, const std::vector<int>& indices, const std::optional<Eigen::Vector3f>& up,
                    float noise) {
  const std::vector<Eigen::Vector3f> points = withoutSparseCells(usablePoints(cloud, indices));
  if (points.empty()) return ObjectBox{};
  const float max_pull = std::isfinite(noise) && noise > 0.0f ? kNoisePullSigmas * noise : 0.0f;
  if (up && up->allFinite() && up->norm() > 0.0f) return gravityAlignedBox(points, up->normalized(), max_pull);
  return principalBox(points, max_pull);
}

std::string boxProblem(const ObjectBox& box) {
  if (!box.center.allFinite() || !box.axes.allFinite() || !box.size.allFinite()) return "box values must be finite";
  if ((box.size.array() < 0.0f).any()) return "box size must not be negative";
  if (!(box.axes.transpose() * box.axes).isApprox(Eigen::Matrix3f::Identity(), 1e-3f) || !(box.axes.determinant() > 0.0f)) {
    return "box axes must be unit, orthogonal and right-handed";
  }
  return "";
}

std::optional<Eigen::Vector3f> supportUp(const SegmentationResult& result) {
  if (result.support && result.support->plane.head<3>().norm() > 0.0f) return result.support->plane.head<3>().normalized();
  return std::nullopt;
}

std::optional<Eigen::Vector3f> boxUp(const Scene& scene, const SegmentationResult& result) {
  if (const auto up = supportUp(result)) return up;
  return scene.up;
}

void addObjectBoxes(const Scene& scene, SegmentationResult& result) {
  if (!scene.cloud) return;
  const std::optional<Eigen::Vector3f> up = boxUp(scene, result);
  const float noise = result.support ? result.support->noise : 0.0f;
  for (Segment& segment : result.segments) segment.box = objectBox(*scene.cloud, segment.indices, up, noise);
}

}  // namespace symmetry_segmentation
