// Stage 2b: vertical symmetry planes proposed from single surfaces (see the header for why).
#include "symmetry_segmentation/symmetry/upright_hypotheses.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <Eigen/Eigenvalues>

#include "symmetry_segmentation/symmetry/point_grid.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {
namespace {

constexpr float kDegToRad = static_cast<float>(M_PI) / 180.0f;
constexpr int kAxisPlaneAngles = 24;     // Planes through an axis tried every 7.5 degrees.
constexpr float kLandingRadius = 0.01f;  // A reflection this close to the surface lands on it (m).
constexpr float kColumnMargin = 0.02f;   // Height margin of the scored column around an axis (m).

struct Surface {
  std::vector<int> points;
};

SymmetryHypothesis verticalPlane(const Eigen::Vector3f& through, Eigen::Vector3f normal, const Eigen::Vector3f& up,
                                 int support) {
  normal -= normal.dot(up) * up;  // Exactly vertical plane.
  SymmetryHypothesis h;
  h.plane.normal = normal.normalized();
  h.plane.distance = -h.plane.normal.dot(through);
  h.plane = canonicalPlane(h.plane);
  h.support = support;
  return h;
}

/// The vertical line closest (least squares) to every point's horizontal normal line; false when
/// the normals do not turn enough to locate it or do not meet near one axis.
bool fitVerticalAxis(const Cloud& cloud, const std::vector<int>& points, const Eigen::Vector3f& up,
                     const UprightHypothesisParams& params, Eigen::Vector3f& axis_point, float& axis_radius) {
  Eigen::Matrix3f a = Eigen::Matrix3f::Zero();
  Eigen::Vector3f b = Eigen::Vector3f::Zero();
  Eigen::Vector3f mean_direction = Eigen::Vector3f::Zero();
  int used = 0;
  for (int i : points) {
    Eigen::Vector3f d = cloud.points[i].getNormalVector3fMap();
    d -= d.dot(up) * up;
    if (d.norm() < 0.3f) continue;  // Near-horizontal surface: its normal line says little.
    d.normalize();
    // Projector onto the plane perpendicular to both the normal line and the vertical.
    const Eigen::Vector3f side = up.cross(d);
    const Eigen::Matrix3f p = side * side.transpose();
    const Eigen::Vector3f x = cloud.points[i].getVector3fMap();
    a += p;
    b += p * x;
    mean_direction += d;
    ++used;
  }
  if (used < params.min_surface_points) return false;
  // A spread of normal directions: |mean of unit vectors| = 1 for a flat face.
  const float spread_cos = mean_direction.norm() / static_cast<float>(used);
  if (spread_cos > std::cos(0.5f * params.min_normal_spread_deg * kDegToRad)) return false;
  // The axis point is only defined horizontally; pin its height with the up direction.
  a += up * up.transpose();
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  for (int i : points) centroid += cloud.points[i].getVector3fMap();
  centroid /= static_cast<float>(points.size());
  b += up * up.dot(centroid);
  axis_point = a.ldlt().solve(b);
  if (!axis_point.allFinite()) return false;

  double squared_residual = 0.0, radius = 0.0;
  for (int i : points) {
    Eigen::Vector3f d = cloud.points[i].getNormalVector3fMap();
    d -= d.dot(up) * up;
    if (d.norm() < 0.3f) continue;
    d.normalize();
    const Eigen::Vector3f offset = axis_point - cloud.points[i].getVector3fMap();
    squared_residual += std::pow(up.cross(d).dot(offset), 2);
    radius += (offset - offset.dot(up) * up).norm();
  }
  // The axis must lie within an object's size of the surface.
  radius /= used;
  axis_radius = static_cast<float>(radius);
  return std::sqrt(squared_residual / used) < params.max_axis_residual && radius < params.max_axis_radius;
}

/// The vertical plane through the axis under which the scene points around it (the object the
/// surface belongs to, as far as it was seen) are best explained by their reflections. A surface
/// is often only a strip of its object, so the strip alone would pick its own bisector.
SymmetryHypothesis bestPlaneThroughAxis(const Cloud& cloud, const ReflectionScore& score,
                                        const std::vector<int>& surface, const Eigen::Vector3f& axis_point,
                                        float axis_radius, const Eigen::Vector3f& up, int support) {
  // The column around the axis, over the surface's own height (what stands on or under the
  // object is not its business).
  float low = std::numeric_limits<float>::max(), high = -std::numeric_limits<float>::max();
  for (int i : surface) {
    const float height = up.dot(cloud.points[i].getVector3fMap());
    low = std::min(low, height);
    high = std::max(high, height);
  }
  low -= kColumnMargin;
  high += kColumnMargin;
  const float reach = 1.2f * axis_radius + kLandingRadius;
  std::vector<int> around;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    Eigen::Vector3f offset = cloud.points[i].getVector3fMap() - axis_point;
    const float height = offset.dot(up) + up.dot(axis_point);
    if (height < low || height > high) continue;
    offset -= offset.dot(up) * up;
    if (offset.squaredNorm() < reach * reach) around.push_back(static_cast<int>(i));
  }
  const Eigen::Vector3f helper = std::fabs(up.x()) < 0.9f ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitY();
  const Eigen::Vector3f e1 = up.cross(helper).normalized();
  const Eigen::Vector3f e2 = up.cross(e1);
  std::vector<SymmetryHypothesis> planes;
  std::vector<float> totals;
  for (int k = 0; k < kAxisPlaneAngles; ++k) {
    const float angle = static_cast<float>(M_PI) * static_cast<float>(k) / kAxisPlaneAngles;
    planes.push_back(verticalPlane(axis_point, std::cos(angle) * e1 + std::sin(angle) * e2, up, support));
    float total = 0.0f;
    for (int i : around) total += score(i, planes.back().plane);
    totals.push_back(total);
  }
  return planes[std::max_element(totals.begin(), totals.end()) - totals.begin()];
}

}  // namespace

ReflectionScore landingScore(const Cloud& cloud) {
  // The closure owns what it needs: it may outlive the caller's cloud.
  auto positions = std::make_shared<std::vector<Eigen::Vector3f>>();
  positions->reserve(cloud.size());
  for (const auto& p : cloud.points) positions->push_back(p.getVector3fMap());
  auto grid = std::make_shared<const PointGrid>(cloud, kLandingRadius);
  return [positions, grid](int index, const SymmetryPlane& plane) {
    const Eigen::Vector3f reflected = reflectPoint(plane, (*positions)[index]);
    bool hit = false;
    grid->forEachWithin(reflected, kLandingRadius, [&](int, float) { hit = true; });
    return hit ? 1.0f : 0.0f;
  };
}

std::vector<SymmetryHypothesis> uprightHypotheses(const Cloud& cloud, const std::vector<int>& labels,
                                                  const Eigen::Vector3f& up, const UprightHypothesisParams& params,
                                                  const ReflectionScore& score) {
  int max_label = 0;
  for (int label : labels) max_label = std::max(max_label, label);
  std::vector<Surface> surfaces(max_label + 1);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] > 0) surfaces[labels[i]].points.push_back(static_cast<int>(i));
  }

  std::vector<SymmetryHypothesis> result;
  const float vertical_sin = std::sin(params.face_tilt_deg * kDegToRad);
  const float horizontal_cos = std::cos(params.face_tilt_deg * kDegToRad);
  for (const Surface& surface : surfaces) {
    const int n = static_cast<int>(surface.points.size());
    if (n < params.min_surface_points) continue;
    Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
    Eigen::Vector3f mean_normal = Eigen::Vector3f::Zero();
    for (int i : surface.points) {
      centroid += cloud.points[i].getVector3fMap();
      mean_normal += cloud.points[i].getNormalVector3fMap();
    }
    centroid /= static_cast<float>(n);
    Eigen::Matrix3f covariance = Eigen::Matrix3f::Zero();
    for (int i : surface.points) {
      const Eigen::Vector3f d = cloud.points[i].getVector3fMap() - centroid;
      covariance += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> pca(covariance);  // Ascending eigenvalues.
    const float curvature = pca.eigenvalues()(0) / std::max(1e-12f, pca.eigenvalues().sum());
    const Eigen::Vector3f face_normal = pca.eigenvectors().col(0);

      // A narrow strip of a curved surface looks flat to PCA; it proposes both kinds of plane
    // (the bisector of its chord passes through the axis as well).
    if (curvature < params.flat_curvature) {
      const float tilt = std::fabs(face_normal.dot(up));
      if (tilt < vertical_sin) {
        result.push_back(verticalPlane(centroid, up.cross(face_normal), up, n));
      } else if (tilt > horizontal_cos) {
        // Principal axes of the face seen from above.
        Eigen::Matrix3f flat = covariance;
        const Eigen::Matrix3f horizontal = Eigen::Matrix3f::Identity() - up * up.transpose();
        flat = horizontal * flat * horizontal;
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> axes(flat);
        result.push_back(verticalPlane(centroid, axes.eigenvectors().col(2), up, n));
        result.push_back(verticalPlane(centroid, axes.eigenvectors().col(1), up, n));
      }
    }
    const bool flat = mean_normal.norm() / static_cast<float>(n) > std::cos(params.flat_normal_spread_deg * kDegToRad);
    if (flat) continue;
    Eigen::Vector3f axis_point;
    float axis_radius = 0.0f;
    if (!fitVerticalAxis(cloud, surface.points, up, params, axis_point, axis_radius)) continue;
    // Any vertical plane through the axis is a symmetry plane of a surface of revolution; the
    // one that maps most of the seen part of the surface onto itself bisects what was seen.
    result.push_back(bestPlaneThroughAxis(cloud, score, surface.points, axis_point, axis_radius, up, n));
  }
  return result;
}

void appendDistinctHypotheses(std::vector<SymmetryHypothesis>& base, const std::vector<SymmetryHypothesis>& extra,
                              float max_angle_deg, float max_distance) {
  for (const SymmetryHypothesis& candidate : extra) {
    bool known = false;
    for (const SymmetryHypothesis& h : base) {
      if (planeAngleDeg(h.plane, candidate.plane) < max_angle_deg &&
          planeDistanceDifference(h.plane, candidate.plane) < max_distance) {
        known = true;
        break;
      }
    }
    if (!known) base.push_back(candidate);
  }
}

}  // namespace symmetry_segmentation
