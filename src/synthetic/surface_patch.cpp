#include "symmetry_segmentation/synthetic/surface_patch.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace symmetry_segmentation {
namespace synthetic {
namespace {

constexpr double kTiny = 1e-12;

/// Roots of a*t^2 + 2*b*t + c = 0 in increasing order; false when there are none.
bool solveQuadratic(double a, double b, double c, double& t0, double& t1) {
  if (std::abs(a) < kTiny) {
    if (std::abs(b) < kTiny) return false;
    t0 = t1 = -c / (2.0 * b);
    return true;
  }
  const double discriminant = b * b - a * c;
  if (discriminant < 0.0) return false;
  const double root = std::sqrt(discriminant);
  // Numerically stable form: avoid subtracting nearly equal numbers.
  const double q = b >= 0.0 ? -(b + root) : -(b - root);
  double r0 = q / a;
  double r1 = std::abs(q) > kTiny ? c / q : r0;
  if (r0 > r1) std::swap(r0, r1);
  t0 = r0;
  t1 = r1;
  return true;
}

}  // namespace

std::optional<SurfaceHit> intersect(const BoxSolid& box, const Ray& ray, double t_min, double t_max) {
  double t_near = -std::numeric_limits<double>::infinity();
  double t_far = std::numeric_limits<double>::infinity();
  int near_axis = -1;
  double near_sign = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double o = ray.origin[axis];
    const double d = ray.direction[axis];
    if (std::abs(d) < kTiny) {
      if (o < box.min[axis] || o > box.max[axis]) return std::nullopt;
      continue;
    }
    double t0 = (box.min[axis] - o) / d;
    double t1 = (box.max[axis] - o) / d;
    // Entering through the min face means the outward normal is -axis.
    double sign = -1.0;
    if (t0 > t1) {
      std::swap(t0, t1);
      sign = 1.0;
    }
    if (t0 > t_near) {
      t_near = t0;
      near_axis = axis;
      near_sign = sign;
    }
    t_far = std::min(t_far, t1);
    if (t_near > t_far) return std::nullopt;
  }
  // Rays starting inside the box see no entry face: the camera is never inside a solid.
  if (near_axis < 0 || t_near < t_min || t_near > t_max) return std::nullopt;
  SurfaceHit hit;
  hit.t = t_near;
  hit.normal = Eigen::Vector3d::Zero();
  hit.normal[near_axis] = near_sign;
  return hit;
}

std::optional<SurfaceHit> intersect(const CylinderSide& side, const Ray& ray, double t_min, double t_max) {
  const Eigen::Vector3d& o = ray.origin;
  const Eigen::Vector3d& d = ray.direction;
  const double a = d.x() * d.x() + d.y() * d.y();
  if (a < kTiny) return std::nullopt;  // parallel to the axis
  const double b = o.x() * d.x() + o.y() * d.y();
  const double c = o.x() * o.x() + o.y() * o.y() - side.radius * side.radius;
  double roots[2];
  if (!solveQuadratic(a, b, c, roots[0], roots[1])) return std::nullopt;
  for (double t : roots) {
    if (t < t_min || t > t_max) continue;
    const Eigen::Vector3d p = ray.at(t);
    if (p.z() < side.z_min || p.z() > side.z_max) continue;
    SurfaceHit hit;
    hit.t = t;
    hit.normal = Eigen::Vector3d(p.x(), p.y(), 0.0).normalized();
    if (!side.normal_outward) hit.normal = -hit.normal;
    return hit;
  }
  return std::nullopt;
}

std::optional<SurfaceHit> intersect(const Annulus& ring, const Ray& ray, double t_min, double t_max) {
  if (std::abs(ray.direction.z()) < kTiny) return std::nullopt;
  const double t = (ring.z - ray.origin.z()) / ray.direction.z();
  if (t < t_min || t > t_max) return std::nullopt;
  const Eigen::Vector3d p = ray.at(t);
  const double r2 = p.x() * p.x() + p.y() * p.y();
  if (r2 < ring.r_inner * ring.r_inner || r2 > ring.r_outer * ring.r_outer) return std::nullopt;
  SurfaceHit hit;
  hit.t = t;
  hit.normal = Eigen::Vector3d(0.0, 0.0, ring.normal_up ? 1.0 : -1.0);
  return hit;
}

std::optional<SurfaceHit> intersect(const FrustumSide& side, const Ray& ray, double t_min, double t_max) {
  const double height = side.z_top - side.z_bottom;
  if (height <= 0.0) return std::nullopt;
  // Radius along the ray: r(t) = q0 + q1 * t; the surface is x^2 + y^2 = r^2 with r >= 0.
  const double slope = (side.r_top - side.r_bottom) / height;
  const Eigen::Vector3d& o = ray.origin;
  const Eigen::Vector3d& d = ray.direction;
  const double q0 = side.r_bottom + slope * (o.z() - side.z_bottom);
  const double q1 = slope * d.z();
  const double a = d.x() * d.x() + d.y() * d.y() - q1 * q1;
  const double b = o.x() * d.x() + o.y() * d.y() - q0 * q1;
  const double c = o.x() * o.x() + o.y() * o.y() - q0 * q0;
  double roots[2];
  if (!solveQuadratic(a, b, c, roots[0], roots[1])) return std::nullopt;
  for (double t : roots) {
    if (t < t_min || t > t_max) continue;
    const Eigen::Vector3d p = ray.at(t);
    if (p.z() < side.z_bottom || p.z() > side.z_top) continue;
    const double r = q0 + q1 * t;
    if (r < 0.0) continue;  // the mirrored nappe of the cone
    const Eigen::Vector3d gradient(p.x(), p.y(), -r * slope);
    if (gradient.norm() < kTiny) continue;  // exactly at the apex
    SurfaceHit hit;
    hit.t = t;
    hit.normal = gradient.normalized();
    return hit;
  }
  return std::nullopt;
}

std::optional<SurfaceHit> intersect(const SphereZone& zone, const Ray& ray, double t_min, double t_max) {
  const Eigen::Vector3d oc = ray.origin - zone.center;
  const double a = ray.direction.squaredNorm();
  const double b = oc.dot(ray.direction);
  const double c = oc.squaredNorm() - zone.radius * zone.radius;
  double roots[2];
  if (!solveQuadratic(a, b, c, roots[0], roots[1])) return std::nullopt;
  for (double t : roots) {
    if (t < t_min || t > t_max) continue;
    const Eigen::Vector3d p = ray.at(t);
    if (p.z() < zone.z_min || p.z() > zone.z_max) continue;
    SurfaceHit hit;
    hit.t = t;
    hit.normal = (p - zone.center).normalized();
    if (!zone.normal_outward) hit.normal = -hit.normal;
    return hit;
  }
  return std::nullopt;
}

std::optional<SurfaceHit> intersect(const SurfacePatch& patch, const Ray& ray, double t_min, double t_max) {
  return std::visit([&](const auto& p) { return intersect(p, ray, t_min, t_max); }, patch);
}

namespace {

struct BoundsVisitor {
  Eigen::Vector3d& min;
  Eigen::Vector3d& max;
  void operator()(const BoxSolid& box) const {
    min = box.min;
    max = box.max;
  }
  void operator()(const CylinderSide& side) const {
    min = Eigen::Vector3d(-side.radius, -side.radius, side.z_min);
    max = Eigen::Vector3d(side.radius, side.radius, side.z_max);
  }
  void operator()(const Annulus& ring) const {
    min = Eigen::Vector3d(-ring.r_outer, -ring.r_outer, ring.z);
    max = Eigen::Vector3d(ring.r_outer, ring.r_outer, ring.z);
  }
  void operator()(const FrustumSide& side) const {
    const double r = std::max(side.r_bottom, side.r_top);
    min = Eigen::Vector3d(-r, -r, side.z_bottom);
    max = Eigen::Vector3d(r, r, side.z_top);
  }
  void operator()(const SphereZone& zone) const {
    // Loose but safe: the whole sphere's box clipped to the band.
    min = zone.center.array() - zone.radius;
    max = zone.center.array() + zone.radius;
    min.z() = std::max(min.z(), zone.z_min);
    max.z() = std::min(max.z(), zone.z_max);
  }
};

}  // namespace

void patchBounds(const SurfacePatch& patch, Eigen::Vector3d& min, Eigen::Vector3d& max) {
  std::visit(BoundsVisitor{min, max}, patch);
}

}  // namespace synthetic
}  // namespace symmetry_segmentation
