// Unary costs of the symmetry graph cut (paper eq. 7-10); the formulas are in the header.
#include "symmetry_segmentation/symmetry/reflection_data_term.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {
float angleDeg(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  const float c = std::clamp(a.dot(b), -1.0f, 1.0f);
  return std::acos(c) * 180.0f / static_cast<float>(M_PI);
}

float normalCompatibility(float alpha_deg, const SymmetryCutParams& params) {
  if (alpha_deg <= params.alpha_min_deg) return 1.0f;
  if (alpha_deg >= params.alpha_max_deg) return 0.0f;
  return (params.alpha_max_deg - alpha_deg) / (params.alpha_max_deg - params.alpha_min_deg);
}

float freeSpaceCost(float distance, const SymmetryCutParams& params) {
  if (!(params.dbuf > params.dmax)) return distance > params.dmax ? 1.0f : 0.0f;
  return std::clamp((distance - params.dmax) / (params.dbuf - params.dmax), 0.0f, 1.0f);
}

ReflectionDataTerm::ReflectionDataTerm(const Cloud& cloud, const PointGrid& grid, const Eigen::AlignedBox3f& cloud_box,
                                       const OccupancyGrid& occupancy,
                                       const std::optional<TableTop>& table,
                                       const SymmetryCutParams& params)
    : cloud_(cloud), grid_(grid), cloud_box_(cloud_box), occupancy_(occupancy), table_(table),
      params_(params) {}

float ReflectionDataTerm::heightAboveTable(const Eigen::Vector3f& point) const {
  if (!table_) return std::numeric_limits<float>::infinity();
  return table_->height(point);
}

float ReflectionDataTerm::unobservedWithin(const Eigen::Vector3f& point, float limit) const {
  static const std::vector<Eigen::Vector3f> directions = [] {
    std::vector<Eigen::Vector3f> result;
    for (int x = -1; x <= 1; ++x) {
      for (int y = -1; y <= 1; ++y) {
        for (int z = -1; z <= 1; ++z) {
          if (x != 0 || y != 0 || z != 0) result.push_back(Eigen::Vector3f(x, y, z).normalized());
        }
      }
    }
    return result;
  }();
  for (int step = 1; step <= params_.unobserved_steps; ++step) {
    const float reach = static_cast<float>(step) * params_.dmax;
    if (reach >= limit) break;
    for (const Eigen::Vector3f& direction : directions) {
      if (occupancy_.classify(point + reach * direction) != Occupancy::Free) return reach;
    }
  }
  return limit;
}

ReflectionEvidence ReflectionDataTerm::evaluate(int index, const SymmetryPlane& plane) const {
  const PointT& point = cloud_.points[index];
  const Eigen::Vector3f position = point.getVector3fMap();
  ReflectionEvidence evidence;
  if (!position.allFinite() || !point.getNormalVector3fMap().allFinite()) {
    evidence.landing = ReflectionLanding::Occluded;  // nothing known about it
    return evidence;
  }
  const Eigen::Vector3f reflected = reflectPoint(plane, position);
  const Eigen::Vector3f reflected_normal = reflectDirection(plane, point.getNormalVector3fMap());

  // Candidate counterparts: scene points within dmax of the reflection, the best-matching normal
  // wins. More than one candidate matters at thin walls, where 1 cm voxels of the inner and the
  // outer surface (opposite normals) lie side by side.
  int best = -1;
  float best_strength = -1.0f;
  float best_distance = 0.0f;
  bool hidden_by_surface = false;
  auto consider = [&](int candidate, float distance) {
    const Eigen::Vector3f candidate_normal = cloud_.points[candidate].getNormalVector3fMap();
    if (reflected_normal.dot(candidate_normal) < 0.0f &&
        (reflected - cloud_.points[candidate].getVector3fMap()).dot(candidate_normal) < 0.0f) {
      // The mirrored surface element faces away and lies behind the visible surface at the
      // candidate: the hidden side of a thin wall (a mug's outer wall behind its visible inner
      // wall), which no view could show. Occluded, not a mismatch.
      hidden_by_surface = true;
      return;
    }
    const float alpha = angleDeg(reflected_normal, candidate_normal);
    const float strength = normalCompatibility(alpha, params_);
    if (strength > best_strength || (strength == best_strength && distance < best_distance)) {
      best = candidate;
      best_strength = strength;
      best_distance = distance;
    }
  };
  // (A point on the plane, |p' - p| <= dmax, is found as a candidate counterpart of itself.)
  // Reflections farther than dbuf outside the cloud's box are not near any point.
  const bool near_cloud = cloud_box_.exteriorDistance(reflected) <= params_.dbuf;
  if (near_cloud) {
    grid_.forEachWithin(reflected, params_.dmax,
                        [&](int candidate, float squared) { consider(candidate, std::sqrt(squared)); });
  }
  if (best >= 0) {
    evidence.landing = ReflectionLanding::OnPoint;
    evidence.match = best;
    evidence.distance = best_distance;
    evidence.foreground_strength = best_strength;
    evidence.cost_foreground = 1.0f - best_strength;
    evidence.cost_background = best_strength;
    return evidence;
  }
  // The mirror image of an object standing on the table is the object itself, above the table:
  // a reflection deep below the table contradicts the plane like free space far from any
  // surface. Just below it (within dbuf) the table hides it and plane errors at the base are
  // tolerated.
  const float table_height = heightAboveTable(reflected);
  if (table_height < -params_.dbuf) {
    evidence.landing = ReflectionLanding::Free;
    evidence.cost_foreground = 1.0f;
    return evidence;
  }
  // Occupied space without a point is a surface we did not keep (the table top, a voxel's
  // edge): neither it nor unobserved space contradicts the symmetry.
  if (hidden_by_surface || table_height < 0.0f || occupancy_.classify(reflected) != Occupancy::Free) {
    evidence.landing = ReflectionLanding::Occluded;
    return evidence;
  }
  // A mirrored surface element just outside unobserved space is the hidden side of an object
  // (the back face of a box seen from the front), displaced by less than a voxel by noise and
  // the map's resolution: the rays that carved the free space there passed the object's hidden
  // edge. One step of dmax into the mirrored surface decides.
  if (occupancy_.classify(reflected - params_.dmax * reflected_normal) != Occupancy::Free) {
    evidence.landing = ReflectionLanding::Occluded;
    return evidence;
  }
  // Free space: the penalty grows with the distance to the nearest surface point, saturating
  // at dbuf (so nothing farther needs to be searched).
  float nearest = params_.dbuf;
  if (near_cloud) {
    float nearest_squared = params_.dbuf * params_.dbuf;
    grid_.forEachWithin(reflected, params_.dbuf,
                        [&](int, float squared) { nearest_squared = std::min(nearest_squared, squared); });
    nearest = std::sqrt(nearest_squared);
  }
  nearest = unobservedWithin(reflected, nearest);
  evidence.landing = ReflectionLanding::Free;
  evidence.distance = nearest;
  evidence.cost_foreground = freeSpaceCost(nearest, params_);
  return evidence;
}

}  // namespace symmetry_segmentation
