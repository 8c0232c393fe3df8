#include "symmetry_segmentation/synthetic/synthetic_object.h"

#include <cmath>
#include <limits>

namespace symmetry_segmentation {
namespace synthetic {
namespace {

/// Outline on the table of one patch: rectangles for boxes, polygons for round patches.
std::vector<Eigen::Vector2d> patchOutline(const SurfacePatch& patch) {
  Eigen::Vector3d min, max;
  patchBounds(patch, min, max);
  if (std::holds_alternative<BoxSolid>(patch)) {
    return {{min.x(), min.y()}, {max.x(), min.y()}, {max.x(), max.y()}, {min.x(), max.y()}};
  }
  if (const auto* zone = std::get_if<SphereZone>(&patch)) {
    // Widest circle of the band: the equator when it lies inside the band.
    const double dz_low = zone->z_min - zone->center.z();
    const double dz_high = zone->z_max - zone->center.z();
    double dz = 0.0;
    if (dz_low > 0.0) dz = dz_low;
    if (dz_high < 0.0) dz = dz_high;
    const double radius = std::sqrt(std::max(0.0, zone->radius * zone->radius - dz * dz));
    auto polygon = circumscribedPolygon(radius);
    for (auto& p : polygon) p += zone->center.head<2>();
    return polygon;
  }
  return circumscribedPolygon(0.5 * (max.x() - min.x()));
}

}  // namespace

std::string toString(ObjectShape shape) {
  switch (shape) {
    case ObjectShape::Table: return "table";
    case ObjectShape::Box: return "box";
    case ObjectShape::Cylinder: return "cylinder";
    case ObjectShape::Bottle: return "bottle";
    case ObjectShape::Bowl: return "bowl";
    case ObjectShape::Mug: return "mug";
    case ObjectShape::Cone: return "cone";
    case ObjectShape::LShape: return "l_shape";
    case ObjectShape::UShape: return "u_shape";
    case ObjectShape::Ball: return "ball";
    case ObjectShape::Pot: return "pot";
    case ObjectShape::Book: return "book";
  }
  return "unknown";
}

void addPatch(SyntheticObject& object, const SurfacePatch& patch) {
  Eigen::Vector3d min, max;
  patchBounds(patch, min, max);
  if (object.patches.empty()) {
    object.local_min = min;
    object.local_max = max;
  } else {
    object.local_min = object.local_min.cwiseMin(min);
    object.local_max = object.local_max.cwiseMax(max);
  }
  object.patches.push_back(patch);
  std::vector<Eigen::Vector2d> points = object.footprint;
  for (const auto& p : patchOutline(patch)) points.push_back(p);
  object.footprint = convexHull(points);
}

Footprint SyntheticObject::worldFootprint() const {
  const Eigen::Matrix3d rotation = pose.linear();
  const double yaw = std::atan2(rotation(1, 0), rotation(0, 0));
  return placeFootprint(footprint, pose.translation().head<2>(), yaw);
}

Rgb surfaceColor(const SyntheticObject& object, const Eigen::Vector3d& world_point) {
  if (!object.print.enabled || object.print.block <= 0.0) return object.color;
  const Eigen::Vector3d local = object.pose.inverse() * world_point;
  // Hash the block's integer coordinates with the print's seed (splitmix64 finaliser).
  uint64_t h = object.print.seed;
  for (int i = 0; i < 3; ++i) {
    const auto cell = static_cast<int64_t>(std::floor(local[i] / object.print.block));
    h ^= static_cast<uint64_t>(cell) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
    h ^= h >> 31;
  }
  const double draw = static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0);
  if (draw >= object.print.ink_share) return object.color;
  const auto ink = static_cast<std::size_t>(draw / object.print.ink_share * object.print.inks.size());
  return object.print.inks[std::min(ink, object.print.inks.size() - 1)];
}

Eigen::Isometry3d uprightPose(double x, double y, double z, double yaw) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(x, y, z);
  return pose;
}

std::optional<ObjectHit> rayIntersect(const SyntheticObject& object, const Ray& world_ray, double t_min,
                                      double t_max) {
  // Work in the local frame: t is unchanged by a rigid transform of origin and direction.
  const Eigen::Matrix3d to_local = object.pose.linear().transpose();
  Ray ray;
  ray.origin = to_local * (world_ray.origin - object.pose.translation());
  ray.direction = to_local * world_ray.direction;

  // Cheap rejection: the ray's line must cross the local bounding box before t_max (a start
  // inside the box or a box behind the ray still passes; the patches decide then).
  const BoxSolid bounds{object.local_min.array() - 1e-6, object.local_max.array() + 1e-6};
  if (!intersect(bounds, ray, -std::numeric_limits<double>::infinity(), t_max)) return std::nullopt;

  std::optional<SurfaceHit> best;
  for (const auto& patch : object.patches) {
    const double limit = best ? best->t : t_max;
    auto hit = intersect(patch, ray, t_min, limit);
    if (hit && (!best || hit->t < best->t)) best = hit;
  }
  if (!best) return std::nullopt;
  ObjectHit result;
  result.t = best->t;
  result.point = world_ray.at(best->t);
  result.normal = object.pose.linear() * best->normal;
  return result;
}

}  // namespace synthetic
}  // namespace symmetry_segmentation
