// Stage 20, completion: each segment's unseen side from its symmetry (see the header for why).
#include "symmetry_segmentation/symmetry/completion.h"

#include <algorithm>
#include <cstdint>
#include <unordered_set>
#include <cassert>
#include <iterator>
#include <cmath>
#include <map>
#include <unordered_map>
#include <set>
#include <limits>

#include "symmetry_segmentation/table_grid.h"
#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/quantile.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/sorted_indices.h"
#include "symmetry_segmentation/object_box.h"
#include "symmetry_segmentation/preprocessing.h"
#include "symmetry_segmentation/symmetry/coaxial_pieces.h"
#include "symmetry_segmentation/symmetry/object_size.h"
#include "symmetry_segmentation/symmetry/reflection_data_term.h"
#include "symmetry_segmentation/symmetry/symmetric_graph_cut.h"
#include "symmetry_segmentation/symmetry/upright_hypotheses.h"
#include "symmetry_segmentation/symmetry/symmetry_plane.h"
#include "symmetry_segmentation/voxel_grid.h"

namespace symmetry_segmentation {
namespace {
// A surface of revolution seen from one side spans twice its radius; from all sides too.
constexpr float kMaxRadiusShare = 0.6f;
constexpr float kHeightSlice = 0.02f;         // m
constexpr float kMaxRadiusDeviation = 0.08f;  // median deviation from the slice's median radius, of the radius
constexpr float kGrowMargin = 0.01f;          // m, the working voxel
constexpr float kMaxAxisShift = 0.02f;        // m, refinedRevolutionAxis
constexpr int kAxisFitIterations = 10;
constexpr float kMaxRoundDeviation = 0.1f;    // of the slice's median radius, roundPoints
// Added points past the visible box continue the object: no gap wider than this along the
// box's axis, and at least this many of them.
constexpr float kMaxHiddenSideGap = 0.03f;  // m
constexpr std::size_t kMinHiddenSidePoints = 3;
// An object stands on another segment when that one's points lie under this share of its columns.
constexpr float kMinStandingOnShare = 0.25f;
// A box turned further than ~8 deg off the support's up does not stand on it with its bottom.
constexpr float kUprightBoxCos = 0.99f;
// A column's lowest point is on a side (not a top or bottom face) when its normal is within 45 deg
// of horizontal; a column reaching within 1.5 cells of the support is grounded (the support's
// own points are observed there).
constexpr float kMaxSideNormalUp = 0.7071f;
constexpr float kGroundReachCells = 1.5f;
constexpr float kMinGroundedSideShare = 0.5f;

/// Of `sorted` (ascending), the range [low', high'] that continues [low, high]: outwards from it
/// over the values, up to the first gap wider than `max_gap`.
std::pair<float, float> contiguousReach(const std::vector<float>& sorted, float low, float high, float max_gap) {
  float reach_low = low, reach_high = high;
  for (auto it = std::lower_bound(sorted.begin(), sorted.end(), low); it != sorted.begin();) {
    --it;
    if (reach_low - *it > max_gap) break;
    reach_low = *it;
  }
  for (auto it = std::upper_bound(sorted.begin(), sorted.end(), high); it != sorted.end(); ++it) {
    if (*it - reach_high > max_gap) break;
    reach_high = *it;
  }
  return {reach_low, reach_high};
}

/// The 2 cm height slice p lies in: a round object's radius is measured per slice.
long heightSlice(const Eigen::Vector3f& p, const Eigen::Vector3f& up) {
  return std::lround(std::floor(up.dot(p) / kHeightSlice));
}

/// The same plane with a unit normal (planes from files or tests may come scaled).
SymmetryPlane unitPlane(const SymmetryPlane& plane) {
  const float length = plane.normal.norm();
  if (!(length > 0.0f)) return plane;
  return SymmetryPlane{plane.normal / length, plane.distance / length};
}

/// Whether p lies in `box` grown by `margin` on every side.
bool insideBox(const ObjectBox& box, const Eigen::Vector3f& p, float margin) {
  const Eigen::Vector3f local = box.axes.transpose() * (p - box.center);
  return (local.cwiseAbs().array() <= (0.5f * box.size).array() + margin).all() && box.size.maxCoeff() > 0.0f;
}

}  // namespace

std::vector<Eigen::Vector3f> hiddenSideReflections(const SceneEvidence& evidence, const std::vector<int>& points,
                                                   const SymmetryPlane& plane,
                                                   const std::function<bool(const Eigen::Vector3f&)>& hidden) {
  const Cloud& cloud = evidence.cloud();
  std::vector<Eigen::Vector3f> result;
  for (int index : points) {
    const Eigen::Vector3f position = cloud.points[index].getVector3fMap();
    if (!position.allFinite()) continue;
    // The data term calls more than unobserved space "occluded" (the hidden side of a thin
    // wall next to its visible side, free space just outside unobserved space, just under the
    // table): for completion the reflection must be hidden as well.
    if (evidence.reflection(index, plane).landing != ReflectionLanding::Occluded) continue;
    const Eigen::Vector3f reflected = reflectPoint(plane, position);
    if (hidden(reflected)) result.push_back(reflected);
  }
  return result;
}

std::vector<Eigen::Vector3f> revolvedHiddenPoints(const std::vector<Eigen::Vector3f>& points,
                                                  const Eigen::Vector3f& axis_point, const Eigen::Vector3f& up,
                                                  int steps, const std::function<bool(const Eigen::Vector3f&)>& hidden) {
  std::vector<Eigen::Vector3f> result;
  for (int k = 1; k < steps; ++k) {
    const Eigen::AngleAxisf turn(2.0f * static_cast<float>(M_PI) * static_cast<float>(k) / static_cast<float>(steps), up);
    for (const Eigen::Vector3f& p : points) {
      const Eigen::Vector3f q = axis_point + turn * (p - axis_point);
      if (hidden(q)) result.push_back(q);
    }
  }
  return result;
}

std::vector<int> revolutionSurface(const Cloud& cloud, const std::vector<int>& points, const Eigen::Vector3f& axis_point,
                                   const Eigen::Vector3f& up, const UprightHypothesisParams& axes) {
  const float max_residual = axes.max_axis_residual;
  std::vector<int> surface;
  std::vector<float> radii;
  for (int i : points) {
    Eigen::Vector3f normal;
    if (!horizontalNormal(cloud, i, up, normal)) continue;
    Eigen::Vector3f offset = axis_point - cloud[i].getVector3fMap();
    offset -= offset.dot(up) * up;
    if (std::fabs(up.cross(normal).dot(offset)) >= max_residual) continue;
    surface.push_back(i);
    radii.push_back(offset.norm());
  }
  if (surface.empty()) return surface;
  // The widest horizontal extent of the points: over a few directions about up.
  const Eigen::Vector3f u = up.unitOrthogonal();
  const Eigen::Vector3f v = up.cross(u);
  float widest = 0.0f;
  for (int k = 0; k < 8; ++k) {
    const float angle = static_cast<float>(M_PI) * static_cast<float>(k) / 8.0f;
    const Eigen::Vector3f direction = std::cos(angle) * u + std::sin(angle) * v;
    float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
    for (int i : points) {
      low = std::min(low, direction.dot(cloud[i].getVector3fMap()));
      high = std::max(high, direction.dot(cloud[i].getVector3fMap()));
    }
    widest = std::max(widest, high - low);
  }
  // Round: at one height, the same distance from the axis (a box's faces are nearer the axis
  // in their middle than at their edges, by up to 40 %).
  std::map<long, std::vector<float>> by_height;
  for (std::size_t k = 0; k < surface.size(); ++k) {
    by_height[heightSlice(cloud[surface[k]].getVector3fMap(), up)].push_back(radii[k]);
  }
  std::vector<float> deviations;
  for (auto& [slice, slice_radii] : by_height) {
    std::vector<float> copy = slice_radii;
    const float middle = quantileOf(copy, 0.5f);
    for (float r : slice_radii) deviations.push_back(std::fabs(r - middle));
  }
  std::vector<float> all_radii = radii;
  const float radius = quantileOf(all_radii, 0.5f);
  if (radius > kMaxRadiusShare * widest) return {};
  if (quantileOf(deviations, 0.5f) > kMaxRadiusDeviation * radius) return {};
  // Normals that turn continuously: the middles of a box's faces are round about its centre line.
  if (!coversAnArc(cloud, surface, up, axes)) return {};
  return surface;
}

namespace {
/// The horizontal offset of p from the vertical axis through axis_point.
Eigen::Vector3f radialOffset(const Eigen::Vector3f& p, const Eigen::Vector3f& axis_point, const Eigen::Vector3f& up) {
  const Eigen::Vector3f offset = p - axis_point;
  return offset - offset.dot(up) * up;
}
}  // namespace

Eigen::Vector3f refinedRevolutionAxis(const std::vector<Eigen::Vector3f>& surface, const Eigen::Vector3f& axis_point,
                                      const Eigen::Vector3f& up) {
  if (surface.size() < 3) return axis_point;
  // In the horizontal plane (u, v): the centre c, each slice's radius its points' mean distance
  // from c; Gauss-Newton on the centre, the radii re-measured each step.
  const Eigen::Vector3f u = up.unitOrthogonal();
  const Eigen::Vector3f v = up.cross(u);
  std::vector<Eigen::Vector2f> flat;
  std::vector<long> slice;
  flat.reserve(surface.size());
  slice.reserve(surface.size());
  for (const Eigen::Vector3f& p : surface) {
    flat.emplace_back(u.dot(p), v.dot(p));
    slice.push_back(heightSlice(p, up));
  }
  const Eigen::Vector2f start(u.dot(axis_point), v.dot(axis_point));
  Eigen::Vector2f centre = start;
  for (int iteration = 0; iteration < kAxisFitIterations; ++iteration) {
    std::unordered_map<long, std::pair<float, int>> radius_sums;
    for (std::size_t k = 0; k < flat.size(); ++k) {
      auto& sum = radius_sums[slice[k]];
      sum.first += (flat[k] - centre).norm();
      ++sum.second;
    }
    Eigen::Matrix2f normal_matrix = Eigen::Matrix2f::Zero();
    Eigen::Vector2f gradient = Eigen::Vector2f::Zero();
    for (std::size_t k = 0; k < flat.size(); ++k) {
      const Eigen::Vector2f d = flat[k] - centre;
      const float distance = d.norm();
      if (!(distance > 1e-6f)) continue;
      const auto& sum = radius_sums[slice[k]];
      const Eigen::Vector2f jacobian = -d / distance;
      normal_matrix += jacobian * jacobian.transpose();
      gradient += jacobian * (distance - sum.first / static_cast<float>(sum.second));
    }
    // A straight row of points (a flat face) leaves the centre undetermined.
    if (!(std::fabs(normal_matrix.determinant()) > 1e-9f)) return axis_point;
    centre -= normal_matrix.inverse() * gradient;
  }
  if (!centre.allFinite() || (centre - start).norm() > kMaxAxisShift) return axis_point;
  return axis_point + (centre.x() - start.x()) * u + (centre.y() - start.y()) * v;
}

std::vector<Eigen::Vector3f> roundPoints(const std::vector<Eigen::Vector3f>& surface, const Eigen::Vector3f& axis_point,
                                         const Eigen::Vector3f& up) {
  std::map<long, std::vector<float>> radii;
  for (const Eigen::Vector3f& p : surface) radii[heightSlice(p, up)].push_back(radialOffset(p, axis_point, up).norm());
  std::map<long, float> median;
  for (auto& [slice, values] : radii) median[slice] = quantileOf(values, 0.5f);
  std::vector<Eigen::Vector3f> round;
  for (const Eigen::Vector3f& p : surface) {
    const float m = median[heightSlice(p, up)];
    if (std::fabs(radialOffset(p, axis_point, up).norm() - m) <= kMaxRoundDeviation * m) round.push_back(p);
  }
  return round;
}

std::vector<Eigen::Vector3f> onePerCell(const std::vector<Eigen::Vector3f>& points, float cell) {
  std::set<std::array<std::int64_t, 3>> taken;
  std::vector<Eigen::Vector3f> result;
  for (const Eigen::Vector3f& p : points) {
    if (taken.insert(voxelKey(p, cell)).second) result.push_back(p);
  }
  return result;
}

std::vector<int> surfacePoints(const Cloud& cloud, const pcl::KdTreeFLANN<PointT>& tree, const std::vector<int>& points,
                               float radius, int min_neighbours) {
  std::vector<char> member(cloud.size(), 0);
  for (int i : points) {
    assert(i >= 0 && static_cast<std::size_t>(i) < cloud.size());
    member[i] = 1;
  }
  std::vector<int> surface;
  std::vector<int> near;
  std::vector<float> squared;
  for (int i : points) {
    if (!cloud.points[i].getVector3fMap().allFinite()) continue;
    tree.radiusSearch(cloud.points[i], radius, near, squared);
    const auto others = std::count_if(near.begin(), near.end(), [&](int j) { return j != i && member[j]; });
    if (others >= min_neighbours) surface.push_back(i);
  }
  return surface;
}

bool planeNearPoints(const Cloud& cloud, const std::vector<int>& points, const SymmetryPlane& given,
                     const std::optional<Eigen::Vector3f>& up) {
  if (points.empty()) return false;
  const SymmetryPlane plane = unitPlane(given);
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  for (int index : points) centroid += cloud.points[index].getVector3fMap();
  centroid /= static_cast<float>(points.size());
  const float largest = segmentExtents(cloud, points, up).maxCoeff();
  return std::fabs(plane.normal.dot(centroid) + plane.distance) <= 0.5f * largest;
}

std::vector<Eigen::Vector3f> groundedSidePoints(const Cloud& cloud, const std::vector<int>& points,
                                                const TableTop& support, float cell,
                                                const std::function<bool(const Eigen::Vector3f&)>& hidden) {
  if (!(support.plane.head<3>().norm() > 0.0f)) return {};
  const Eigen::Vector3f up = support.plane.head<3>().normalized();
  const Eigen::Vector3f u = up.unitOrthogonal();
  const Eigen::Vector3f v = up.cross(u);
  std::map<std::pair<long, long>, int> lowest;  // column -> index of its lowest point
  for (int i : points) {
    const Eigen::Vector3f p = cloud.points[i].getVector3fMap();
    if (!p.allFinite()) continue;
    const std::pair<long, long> column(std::lround(std::floor(u.dot(p) / cell)), std::lround(std::floor(v.dot(p) / cell)));
    const auto found = lowest.find(column);
    if (found == lowest.end() || up.dot(p) < up.dot(cloud.points[found->second].getVector3fMap())) lowest[column] = i;
  }
  std::vector<Eigen::Vector3f> result;
  std::vector<Eigen::Vector3f> column_points;
  std::size_t sides = 0, grounded = 0;
  for (const auto& [column, i] : lowest) {
    const Eigen::Vector3f normal = cloud.points[i].getNormalVector3fMap();
    if (!normal.allFinite() || std::fabs(normal.dot(up)) > kMaxSideNormalUp) continue;  // a top or bottom face
    ++sides;
    const Eigen::Vector3f start = cloud.points[i].getVector3fMap();
    const float height = support.height(start);
    column_points.clear();
    bool reached = false;
    for (float drop = cell; height - drop > 0.0f; drop += cell) {
      if (height - drop < kGroundReachCells * cell) {
        reached = true;
        break;
      }
      const Eigen::Vector3f q = start - drop * up;
      if (!hidden(q)) break;
      column_points.push_back(q);
    }
    if (!reached) continue;
    ++grounded;
    result.insert(result.end(), column_points.begin(), column_points.end());
  }
  // Most of its sides must reach the support: an object whose sides mostly stop on something
  // stands on that (a box on a box, whose hidden back runs on down beside the lower one's
  // unseen back).
  if (grounded < kMinGroundedSideShare * sides) return {};
  return result;
}

ObjectBox groundedBox(ObjectBox box, const std::vector<Eigen::Vector3f>& grounded) {
  if (grounded.empty()) return box;
  const Eigen::Vector3f z = box.axes.col(2);
  float lowest = std::numeric_limits<float>::max();
  for (const Eigen::Vector3f& p : grounded) lowest = std::min(lowest, z.dot(p));
  const float bottom = z.dot(box.center) - 0.5f * box.size.z();
  if (!(lowest < bottom)) return box;
  const float top = bottom + box.size.z();
  box.center += 0.5f * (lowest - bottom) * z;
  box.size.z() = top - lowest;
  return box;
}

ObjectBox restingBox(ObjectBox box, const TableTop& support, float reach) {
  const float norm = support.plane.head<3>().norm();
  if (!(norm > 0.0f)) return box;
  const Eigen::Vector3f z = box.axes.col(2);
  const Eigen::Vector3f bottom_centre = box.center - 0.5f * box.size.z() * z;
  const float cos_up = support.plane.head<3>().dot(z) / norm;
  if (cos_up < kUprightBoxCos) return box;  // a box not along the support's up
  // How far down along z the support is from the bottom's centre.
  const float gap = support.height(bottom_centre) / cos_up;
  if (!(gap > 0.0f && gap < reach)) return box;
  box.center -= 0.5f * gap * z;
  box.size.z() += gap;
  return box;
}

ObjectColumns::ObjectColumns(const ObjectBox& box, const Cloud& cloud, const std::vector<int>& own, float cell)
    : box_(box), cloud_(cloud), cell_(cell) {
  if (!(cell > 0.0f)) return;
  for (int index : own) columns_.insert(column(local(index)));
}

Eigen::Vector3f ObjectColumns::local(int index) const {
  return box_.axes.transpose() * (cloud_.points[index].getVector3fMap() - box_.center);
}

std::int64_t ObjectColumns::column(const Eigen::Vector3f& local_point) const {
  return TableGrid::key(static_cast<std::int64_t>(std::floor(local_point.x() / cell_)),
                        static_cast<std::int64_t>(std::floor(local_point.y() / cell_)));
}

bool ObjectColumns::standsOn(const std::vector<int>& others) const {
  if (columns_.empty()) return false;
  const float under = -0.5f * box_.size.z() + cell_;
  std::unordered_set<std::int64_t> covered;
  for (int index : others) {
    const Eigen::Vector3f p = local(index);
    if (p.z() < under && columns_.count(column(p)) > 0) covered.insert(column(p));
  }
  // A neighbour touching its side shares its edge's columns; what it stands on is under many.
  return static_cast<float>(covered.size()) >= kMinStandingOnShare * static_cast<float>(columns_.size());
}

ObjectBox completedBox(const std::vector<Eigen::Vector3f>& visible, const std::vector<Eigen::Vector3f>& added,
                       const std::optional<Eigen::Vector3f>& up, float trim, float noise) {
  Cloud seen_cloud;
  seen_cloud.reserve(visible.size());
  for (const Eigen::Vector3f& p : visible) {
    PointT point;
    point.getVector3fMap() = p;
    seen_cloud.push_back(point);
  }
  // Turned as the visible points are: their footprint is measured, the added one inferred through
  // a plane that may be a few degrees off (turning the box with it was worse on single views).
  std::vector<int> seen(visible.size());
  for (std::size_t i = 0; i < seen.size(); ++i) seen[i] = static_cast<int>(i);
  ObjectBox box = objectBox(seen_cloud, seen, up, noise);
  if (visible.empty() || added.empty()) return box;
  // The visible box's extent (without its stray points), grown where the added points pass it by
  // more than a working voxel: within that they only restate the visible side, a plane a degree
  // off or noisy points turned about an axis. On generated single Kinect views (seeds 1-2)
  // median completed box IoU 0.790 to 0.807, RealSense 0.650 to 0.660, fused 0.921 to 0.925.
  // Only by added points that continue the object (see the header): a few reflections of points
  // the visible box leaves out as strays land far from it.
  Eigen::Vector3f low = box.axes.transpose() * box.center - 0.5f * box.size;
  Eigen::Vector3f high = low + box.size;
  for (int k = 0; k < 3; ++k) {
    std::vector<float> along;
    along.reserve(added.size());
    for (const Eigen::Vector3f& p : added) along.push_back(box.axes.col(k).dot(p));
    std::sort(along.begin(), along.end());
    const auto [reach_low, reach_high] = contiguousReach(along, low[k], high[k], kMaxHiddenSideGap);
    std::vector<float> connected;
    std::copy_if(along.begin(), along.end(), std::back_inserter(connected),
                 [&](float a) { return a >= reach_low && a <= reach_high; });
    if (connected.empty()) continue;
    const auto past = [&](auto beyond) {
      return static_cast<std::size_t>(std::count_if(connected.begin(), connected.end(), beyond)) >= kMinHiddenSidePoints;
    };
    const bool past_low = past([&](float a) { return a < low[k] - kGrowMargin; });
    const bool past_high = past([&](float a) { return a > high[k] + kGrowMargin; });
    const auto [added_low, added_high] = trimmedRange(connected, trim);
    if (past_low && added_low < low[k] - kGrowMargin) low[k] = added_low;
    if (past_high && added_high > high[k] + kGrowMargin) high[k] = added_high;
  }
  box.center = box.axes * (0.5f * (low + high));
  box.size = high - low;
  return box;
}

Eigen::Isometry3f symmetryFrame(const Eigen::Vector3f& centroid, const SymmetryPlane& given,
                                const std::optional<Eigen::Vector3f>& up) {
  const SymmetryPlane plane = unitPlane(given);
  const Eigen::Vector3f x = plane.normal;
  Eigen::Vector3f z = x.unitOrthogonal();
  if (up) {
    const Eigen::Vector3f vertical = *up - up->dot(x) * x;
    if (vertical.norm() > 1e-3f * up->norm()) z = vertical.normalized();
  }
  Eigen::Matrix3f axes;
  axes.col(0) = x;
  axes.col(1) = z.cross(x);
  axes.col(2) = z;
  Eigen::Isometry3f frame = Eigen::Isometry3f::Identity();
  frame.linear() = axes;
  frame.translation() = centroid - (x.dot(centroid) + plane.distance) * x;
  return frame;
}

std::vector<int> pointsInBox(const Cloud& cloud, const std::vector<int>& points, const ObjectBox& visible, float margin) {
  std::vector<int> inside;
  inside.reserve(points.size());
  for (int index : points) {
    if (insideBox(visible, cloud.points[index].getVector3fMap(), margin)) inside.push_back(index);
  }
  return inside;
}

namespace {

/// The box the output gives `segment` (objectBox of its input points, strays left out); on the
/// working points when the stage runs without its scene.
ObjectBox visibleBox(const PipelineState& state, const CandidateSegment& segment) {
  const float noise = state.prepared.table_noise;
  if (!state.scene || !state.scene->cloud) return objectBox(*state.cloud, segment.points, state.up, noise);
  const std::optional<Eigen::Vector3f> up = state.up ? state.up : state.scene->up;
  return objectBox(*state.scene->cloud, setUnion(expandToInput(state.prepared, segment.points), segment.extra_input_points), up,
                   noise);
}

}  // namespace

void CompletionStage::run(PipelineState& state) const {
  std::optional<TableTop> table;
  if (state.prepared.has_table) table = state.prepared.tableTop();
  const Cloud& cloud = *state.cloud;
  // Unobserved space (not free) above the table (which hides nothing of an object standing on
  // it) with no observed point within a voxel but those of `own` (sorted; may be null).
  const auto unobserved = [&](const Eigen::Vector3f& q, const std::vector<int>* own) {
    if (table && table->height(q) < 0.0f) return false;
    if (state.occupancy->classify(q) == Occupancy::Free) return false;
    std::vector<int> near;
    std::vector<float> squared;
    PointT query;
    query.getVector3fMap() = q;
    if (!own) return state.graph->tree().radiusSearch(query, voxel_size_, near, squared, 1) == 0;
    state.graph->tree().radiusSearch(query, voxel_size_, near, squared);
    return std::all_of(near.begin(), near.end(), [&](int j) { return std::binary_search(own->begin(), own->end(), j); });
  };
  const std::function<bool(const Eigen::Vector3f&)> hidden = [&](const Eigen::Vector3f& q) {
    return unobserved(q, nullptr);
  };
  // Each object's visible box: what it completes lies in it, and a column carried down into
  // another's stands on that object.
  std::vector<ObjectBox> boxes;
  boxes.reserve(state.segments.size());
  for (const CandidateSegment& segment : state.segments) boxes.push_back(visibleBox(state, segment));
  std::size_t added = 0, revolved = 0, grounded = 0, resting = 0;
  for (std::size_t s = 0; s < state.segments.size(); ++s) {
    CandidateSegment& segment = state.segments[s];
    std::vector<Eigen::Vector3f> points;
    const std::vector<int> own = pointsInBox(cloud, segment.points, boxes[s], voxel_size_);
    if (planeNearPoints(cloud, segment.points, segment.plane, state.up)) {
      const std::vector<int> on_surface = surfacePoints(cloud, state.graph->tree(), own,
                                                        kSurfaceRadiusVoxels * voxel_size_, kMinSurfaceNeighbours);
      points = hiddenSideReflections(*state.evidence, on_surface, segment.plane, hidden);
    }
    std::optional<Eigen::Vector3f> axis;
    if (state.up && params_.revolution_steps > 1) axis = revolutionAxis(cloud, segment.points, *state.up, axes_, min_axis_share_);
    // The axis and the round surface are fitted to all of the segment (its sheet of table noise
    // is no round surface, and the fit needs every point of a cone's foot); only the surface's
    // points in the box are turned.
    const std::vector<int> surface =
        axis ? intersection(revolutionSurface(cloud, segment.points, *axis, *state.up, axes_), own) : std::vector<int>{};
    if (!surface.empty()) {
      std::vector<Eigen::Vector3f> seen;
      seen.reserve(surface.size());
      for (int index : surface) seen.push_back(cloud.points[index].getVector3fMap());
      const Eigen::Vector3f axis_point = refinedRevolutionAxis(seen, *axis, *state.up);
      const auto turned =
          revolvedHiddenPoints(roundPoints(seen, axis_point, *state.up), axis_point, *state.up, params_.revolution_steps, hidden);
      points.insert(points.end(), turned.begin(), turned.end());
      ++revolved;
    }
    if (table && params_.ground_to_support) {
      // The object's own points beside a column say nothing of what is under it.
      const std::function<bool(const Eigen::Vector3f&)> hidden_under = [&](const Eigen::Vector3f& q) {
        for (std::size_t o = 0; o < boxes.size(); ++o) {
          if (o != s && insideBox(boxes[o], q, 0.5f * voxel_size_)) return false;
        }
        return unobserved(q, &segment.points);
      };
      segment.grounded = onePerCell(groundedSidePoints(cloud, segment.points, *table, voxel_size_, hidden_under), voxel_size_);
      grounded += segment.grounded.size();
    }
    if (table && params_.rest_on_support) {
      const ObjectColumns columns(boxes[s], cloud, segment.points, voxel_size_);
      segment.rests_on_support = std::none_of(state.segments.begin(), state.segments.end(), [&](const CandidateSegment& other) {
        return &other != &segment && columns.standsOn(other.points);
      });
      resting += segment.rests_on_support ? 1 : 0;
    }
    segment.completion = onePerCell(points, voxel_size_);
    added += segment.completion->size();
  }
  state.count("points", added);
  state.count("revolved", revolved);
  state.count("grounded", grounded);
  state.count("resting", resting);
}

}  // namespace symmetry_segmentation
