// Stage 3, upright: vertical symmetry planes proposed from single surfaces (see the header for why).
#include "symmetry_segmentation/symmetry/upright_hypotheses.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <iterator>
#include <memory>
#include <random>

#include <Eigen/Eigenvalues>

#include "symmetry_segmentation/symmetry/mid_height_hypotheses.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"

namespace symmetry_segmentation {
namespace {

constexpr float kDegToRad = static_cast<float>(M_PI) / 180.0f;

SymmetryHypothesis verticalPlane(const Eigen::Vector3f& through, const Eigen::Vector3f& normal,
                                 const Eigen::Vector3f& up, int support) {
  SymmetryHypothesis h;
  h.plane = verticalPlaneThrough(through, normal, up);
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

}  // namespace

bool horizontalNormal(const Cloud& cloud, int i, const Eigen::Vector3f& up, Eigen::Vector3f& d) {
  d = cloud.points[i].getNormalVector3fMap();
  d -= d.dot(up) * up;
  if (d.norm() < 0.3f) return false;
  d.normalize();
  return true;
}

bool coversAnArc(const Cloud& cloud, const std::vector<int>& points, const Eigen::Vector3f& up,
                 const UprightHypothesisParams& params) {
  constexpr int kBins = 36;  // Fixed: 10 degrees each, the step the arc test allows.
  std::vector<int> count(kBins, 0);
  const Eigen::Vector3f helper = std::fabs(up.x()) < 0.9f ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitY();
  const Eigen::Vector3f e1 = up.cross(helper).normalized();
  const Eigen::Vector3f e2 = up.cross(e1);
  for (int i : points) {
    Eigen::Vector3f d;
    if (!horizontalNormal(cloud, i, up, d)) continue;
    const float angle = std::atan2(d.dot(e2), d.dot(e1));
    const int bin = static_cast<int>(std::floor((angle + static_cast<float>(M_PI)) / (2.0f * static_cast<float>(M_PI)) * kBins));
    ++count[std::clamp(bin, 0, kBins - 1)];
  }
  // The longest run of occupied bins (around the circle).
  const int needed = static_cast<int>(std::ceil(params.min_normal_spread_deg / 10.0f)) + 1;
  int longest = 0;
  for (int start = 0; start < kBins; ++start) {
    int run = 0;
    while (run < kBins && count[(start + run) % kBins] > 0) ++run;
    longest = std::max(longest, run);
  }
  return longest >= needed;
}

std::vector<VerticalAxis> fitVerticalAxes(const Cloud& cloud, const std::vector<int>& points, const Eigen::Vector3f& up,
                                          const UprightHypothesisParams& params) {
  constexpr int kSamples = 64;  // Fixed: pairs of normal lines tried per axis (a cost bound).
  std::vector<VerticalAxis> axes;
  std::vector<int> remaining;
  for (int i : points) {
    Eigen::Vector3f d;
    if (horizontalNormal(cloud, i, up, d)) remaining.push_back(i);
  }
  std::mt19937 random(12345u);
  while (static_cast<int>(axes.size()) < params.max_axes_per_surface && static_cast<int>(remaining.size()) >= params.min_surface_points) {
    VerticalAxis axis;
    if (fitVerticalAxis(cloud, remaining, up, params, axis.point, axis.radius)) {
      axis.points = remaining;
      axes.push_back(std::move(axis));
      break;
    }
    // The axis most normal lines pass near: two lines meet at a candidate.
    std::uniform_int_distribution<std::size_t> pick(0, remaining.size() - 1);
    std::vector<int> best_inliers;
    for (int sample = 0; sample < kSamples; ++sample) {
      const int i = remaining[pick(random)];
      const int j = remaining[pick(random)];
      Eigen::Vector3f di, dj;
      horizontalNormal(cloud, i, up, di);
      horizontalNormal(cloud, j, up, dj);
      const float sin_angle = up.dot(di.cross(dj));
      if (std::fabs(sin_angle) < std::sin(params.min_normal_spread_deg * kDegToRad)) continue;
      // x_i + s d_i meets x_j + t d_j (horizontally): s = ((x_j - x_i) x d_j) . up / (d_i x d_j) . up
      const Eigen::Vector3f xi = cloud.points[i].getVector3fMap();
      const Eigen::Vector3f xj = cloud.points[j].getVector3fMap();
      const float s = up.dot((xj - xi).cross(dj)) / sin_angle;
      if (std::fabs(s) > params.max_axis_radius) continue;
      const Eigen::Vector3f candidate = xi + s * di;
      std::vector<int> inliers;
      for (int k : remaining) {
        Eigen::Vector3f dk;
        horizontalNormal(cloud, k, up, dk);
        Eigen::Vector3f offset = candidate - cloud.points[k].getVector3fMap();
        offset -= offset.dot(up) * up;
        if (std::fabs(up.cross(dk).dot(offset)) < params.max_axis_residual && offset.norm() < params.max_axis_radius) {
          inliers.push_back(k);
        }
      }
      if (inliers.size() > best_inliers.size()) best_inliers = std::move(inliers);
    }
    // A share of the surface, not a thin curve across it: on a twisted strip the normal lines
    // of a few points per height pass near any vertical line.
    if (static_cast<int>(best_inliers.size()) < params.min_surface_points ||
        best_inliers.size() < params.min_axis_share * remaining.size()) {
      break;
    }
    if (!coversAnArc(cloud, best_inliers, up, params)) break;
    if (!fitVerticalAxis(cloud, best_inliers, up, params, axis.point, axis.radius)) break;
    std::vector<int> rest;
    std::set_difference(remaining.begin(), remaining.end(), best_inliers.begin(), best_inliers.end(),
                        std::back_inserter(rest));
    axis.points = std::move(best_inliers);
    axes.push_back(std::move(axis));
    remaining = std::move(rest);
  }
  return axes;
}

namespace {

float distanceFromAxis(const Eigen::Vector3f& p, const VerticalAxis& axis, const Eigen::Vector3f& up) {
  Eigen::Vector3f offset = p - axis.point;
  offset -= offset.dot(up) * up;
  return offset.norm();
}

/// The lowest and highest of `points` along `up`, none left out (coaxial_pieces' heightRange
/// trims 5 % at either end).
std::pair<float, float> heightExtent(const Cloud& cloud, const std::vector<int>& points, const Eigen::Vector3f& up) {
  float low = std::numeric_limits<float>::max(), high = -std::numeric_limits<float>::max();
  for (int i : points) {
    const float height = up.dot(cloud.points[i].getVector3fMap());
    low = std::min(low, height);
    high = std::max(high, height);
  }
  return {low, high};
}

/// Whether the round surface of `other` belongs to `axis`'s object. Solid objects do not
/// interpenetrate, so a surface whose axis lies inside this one's column is another strip of
/// it; and a thin round surface against the column's side that fits within `reach` of the axis is
/// a part held by it (a mug's handle, fitted as a thin upright cylinder of its own), not an
/// object standing beside it.
bool partOfObject(const VerticalAxis& other, const VerticalAxis& axis, const Eigen::Vector3f& up, float reach,
                  float tolerance) {
  const float apart = distanceFromAxis(other.point, axis, up);
  if (apart < axis.radius) return true;
  return 2.0f * other.radius < axis.radius && apart + other.radius < reach &&
         apart - other.radius < axis.radius + 2.0f * tolerance;
}

/// Whether p lies on the surface of revolution of one of `others` and not on that of `axis`.
bool onAnotherRoundSurface(const Eigen::Vector3f& p, const VerticalAxis& axis, const std::vector<const VerticalAxis*>& others,
                           const Eigen::Vector3f& up, float tolerance) {
  if (std::fabs(distanceFromAxis(p, axis, up) - axis.radius) < tolerance) return false;
  for (const VerticalAxis* other : others) {
    if (std::fabs(distanceFromAxis(p, *other, up) - other->radius) < tolerance &&
        (other->point - axis.point).norm() > tolerance) {
      return true;
    }
  }
  return false;
}

/// The points of `candidates` linked to `seeds` by chains of steps shorter than `link`.
std::vector<int> pointsAttached(const Cloud& cloud, const std::vector<int>& seeds, std::vector<int> candidates,
                                float link) {
  std::vector<int> attached;
  std::vector<int> frontier = seeds;
  while (!frontier.empty() && !candidates.empty()) {
    std::vector<int> reached, rest;
    for (int c : candidates) {
      const bool linked = std::any_of(frontier.begin(), frontier.end(), [&](int f) {
        return (cloud.points[c].getVector3fMap() - cloud.points[f].getVector3fMap()).squaredNorm() < link * link;
      });
      (linked ? reached : rest).push_back(c);
    }
    attached.insert(attached.end(), reached.begin(), reached.end());
    frontier.swap(reached);
    candidates.swap(rest);
  }
  return attached;
}

/// How a reflection counts when orienting a plane through an axis. Every plane through a true
/// axis is a symmetry, so what decides is contradiction (reflections into free space: a mug's
/// handle mirrored beside it); matches only break ties, else the bisector of whatever arc the
/// views happened to cover would win.
float reflectionScore(const ReflectionEvidence& evidence, const UprightHypothesisParams& params) {
  if (evidence.landing == ReflectionLanding::OnPoint) return params.match_tie_break * evidence.foreground_strength;
  return evidence.landing == ReflectionLanding::Free ? -evidence.cost_foreground : 0.0f;
}

/// The vertical planes through the axis under which the scene points around it (the object the
/// surface belongs to, as far as it was seen) are best explained by their reflections. A surface
/// is often only a strip of its object, so the strip alone would pick its own bisector. One plane,
/// or two when another orientation, nearly as free of contradiction, matches more.
std::vector<SymmetryHypothesis> planesThroughAxis(const SceneEvidence& evidence, const UprightHypothesisParams& params,
                                                  const VerticalAxis& axis, const std::vector<VerticalAxis>& other_axes,
                                                  const Eigen::Vector3f& up) {
  const Cloud& cloud = evidence.cloud();
  const Eigen::Vector3f& axis_point = axis.point;
  const float axis_radius = axis.radius;
  const int support = static_cast<int>(axis.points.size());
  // The column around the axis, over the surface's own height (what stands on or under the
  // object is not its business).
  auto [low, high] = heightExtent(cloud, axis.points, up);
  low -= params.column_height_margin;
  high += params.column_height_margin;
  const float reach = 1.2f * axis_radius + params.surface_tolerance;
  const float attached_reach = std::max(reach, params.attached_reach * axis_radius + params.surface_tolerance);
  std::vector<const VerticalAxis*> neighbours;
  for (const VerticalAxis& other : other_axes) {
    if (&other != &axis && !partOfObject(other, axis, up, attached_reach, params.surface_tolerance)) {
      neighbours.push_back(&other);
    }
  }
  std::vector<int> around, beyond;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    Eigen::Vector3f offset = cloud.points[i].getVector3fMap() - axis_point;
    const float height = offset.dot(up) + up.dot(axis_point);
    if (height < low || height > high) continue;
    offset -= offset.dot(up) * up;
    if (offset.squaredNorm() >= attached_reach * attached_reach) continue;
    // A touching round neighbour's side is its own business: its axis would tilt the choice
    // toward the plane through both axes, and the cut would take both objects.
    if (onAnotherRoundSurface(cloud.points[i].getVector3fMap(), axis, neighbours, up, params.surface_tolerance)) continue;
    (offset.squaredNorm() < reach * reach ? around : beyond).push_back(static_cast<int>(i));
  }
  // A handle sticks out of the column, and it is what orients a mug's plane: mirrored beside
  // itself it lands in free space. Whatever hangs on to the column counts with it.
  const std::vector<int> attached = pointsAttached(cloud, around, beyond, 1.5f * params.surface_tolerance);
  around.insert(around.end(), attached.begin(), attached.end());
  const Eigen::Vector3f helper = std::fabs(up.x()) < 0.9f ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitY();
  const Eigen::Vector3f e1 = up.cross(helper).normalized();
  const Eigen::Vector3f e2 = up.cross(e1);
  // Contradiction first, agreement second: however many points of the seen side a bisector of
  // the seen arc matches, a handle it mirrors into free space rules it out.
  std::vector<SymmetryHypothesis> planes;
  std::vector<float> contradiction, agreement;
  for (int k = 0; k < params.axis_plane_angles; ++k) {
    const float angle = static_cast<float>(M_PI) * static_cast<float>(k) / params.axis_plane_angles;
    planes.push_back(verticalPlane(axis_point, std::cos(angle) * e1 + std::sin(angle) * e2, up, support));
    float against = 0.0f, for_it = 0.0f;
    for (int i : around) {
      const float s = reflectionScore(evidence.reflection(i, planes.back().plane), params);
      (s < 0.0f ? against : for_it) += s;
    }
    contradiction.push_back(-against);
    agreement.push_back(for_it);
  }
  const float least = *std::min_element(contradiction.begin(), contradiction.end());
  int best = -1;
  for (int k = 0; k < params.axis_plane_angles; ++k) {
    if (contradiction[k] > least + params.contradiction_tolerance) continue;
    if (best < 0 || agreement[k] > agreement[best]) best = k;
  }
  // That tolerance is a few points; on a large column the next step of the angle can contradict
  // a little more and still be the plane that keeps the handle: its cut is tried too.
  int second = -1;
  const float share_tolerance = params.second_plane_contradiction_share * static_cast<float>(around.size());
  for (int k = 0; share_tolerance > 0.0f && k < params.axis_plane_angles; ++k) {
    if (contradiction[k] > least + share_tolerance) continue;
    if (second < 0 || agreement[k] > agreement[second]) second = k;
  }
  if (second >= 0 && second != best) return {planes[best], planes[second]};
  return {planes[best]};
}

}  // namespace

std::vector<SymmetryHypothesis> uprightHypotheses(const SceneEvidence& evidence, const std::vector<SurfaceShape>& surfaces,
                                                  const Eigen::Vector3f& up, const UprightHypothesisParams& params) {
  const Cloud& cloud = evidence.cloud();
  std::vector<SymmetryHypothesis> result;
  std::vector<VerticalAxis> axes;
  const float vertical_sin = std::sin(params.face_tilt_deg * kDegToRad);
  const float horizontal_cos = std::cos(params.face_tilt_deg * kDegToRad);
  for (const SurfaceShape& surface : surfaces) {
    const int n = static_cast<int>(surface.points.size());
    if (n < params.min_surface_points) continue;
    const Eigen::Vector3f& centroid = surface.centroid;
    const Eigen::Vector3f& face_normal = surface.face_normal;

    // A narrow strip of a curved surface looks flat to PCA; it proposes both kinds of plane
    // (the bisector of its chord passes through the axis as well).
    if (surface.curvature < params.flat_curvature) {
      const float tilt = std::fabs(face_normal.dot(up));
      if (tilt < vertical_sin) {
        result.push_back(verticalPlane(centroid, up.cross(face_normal), up, n));
      } else if (tilt > horizontal_cos) {
        // Principal axes of the face seen from above.
        const Eigen::Matrix3f horizontal = Eigen::Matrix3f::Identity() - up * up.transpose();
        const Eigen::Matrix3f flat = horizontal * surface.scatter * horizontal;
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> axes(flat);
        result.push_back(verticalPlane(centroid, axes.eigenvectors().col(2), up, n));
        result.push_back(verticalPlane(centroid, axes.eigenvectors().col(1), up, n));
      }
    }
    const bool flat = surface.mean_normal.norm() > std::cos(params.flat_normal_spread_deg * kDegToRad);
    if (flat) continue;
    for (VerticalAxis& axis : fitVerticalAxes(cloud, surface.points, up, params)) axes.push_back(std::move(axis));
  }
  // Any vertical plane through an axis is a symmetry plane of a surface of revolution; the one
  // that maps most of the seen part of the object onto itself bisects what was seen.
  for (const VerticalAxis& axis : axes) {
    for (SymmetryHypothesis& plane : planesThroughAxis(evidence, params, axis, axes, up)) {
      result.push_back(std::move(plane));
      result.back().anchor = axis.points;
    }
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

void UprightStage::run(PipelineState& state) const {
  std::size_t added = 0;
  if (state.up) {
    const std::size_t before = state.hypotheses.size();
    const std::vector<SurfaceShape> shapes = surfaceShapes(*state.cloud, state.surfaces);
    appendDistinctHypotheses(state.hypotheses, uprightHypotheses(*state.evidence, shapes, *state.up, params_),
                             params_.distinct_angle_deg, params_.distinct_distance);
    if (state.prepared.has_table) {
      const std::vector<SymmetryHypothesis> mid =
          midHeightHypotheses(*state.cloud, shapes, state.prepared.tableTop(), params_, voxel_size_);
      state.hypotheses.insert(state.hypotheses.end(), mid.begin(), mid.end());
    }
    added = state.hypotheses.size() - before;
  }
  state.count("hypotheses", added);
}

}  // namespace symmetry_segmentation
