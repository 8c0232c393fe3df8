// Stage 17, object_size: only what a robot could grasp is an object (see the header).
#include "symmetry_segmentation/symmetry/object_size.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include <Eigen/Eigenvalues>
#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>

#include "symmetry_segmentation/point_validity.h"
#include "symmetry_segmentation/quantile.h"
#include "symmetry_segmentation/symmetry/hanging_segments.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/rising_segments.h"
#include "symmetry_segmentation/symmetry/symmetric_graph_cut.h"
#include "symmetry_segmentation/symmetry/table_specks.h"

namespace symmetry_segmentation {
namespace {

constexpr int kPlaneIterations = 200;
// A scrap's height grows with the camera's noise by at most this (4: at twice the table's
// distance); beyond, a frame's far end is better cut by preprocessing.max_range.
constexpr float kMaxNoiseGrowth = 4.0f;
// Points of a segment this many voxels apart are one piece of it; farther, a low piece is a
// speck of the table's noise (table_specks.h). Above the 1.73 voxels of a voxel's diagonal.
constexpr float kPieceLinkVoxels = 2.5f;
// Share of the points left out at either end of an extent.
constexpr float kTrim = 0.05f;

/// Extents of `points` along their principal axes, between the kTrim and 1 - kTrim quantiles:
/// a few stray points of a neighbour or of the background do not make an object large.
template <int Dims>
Eigen::Matrix<float, Dims, 1> principalExtents(const std::vector<Eigen::Matrix<float, Dims, 1>>& points) {
  using Vector = Eigen::Matrix<float, Dims, 1>;
  using Matrix = Eigen::Matrix<float, Dims, Dims>;
  Vector mean = Vector::Zero();
  for (const Vector& p : points) mean += p;
  mean /= static_cast<float>(points.size());
  Matrix covariance = Matrix::Zero();
  for (const Vector& p : points) covariance += (p - mean) * (p - mean).transpose();
  const Matrix axes = Eigen::SelfAdjointEigenSolver<Matrix>(covariance).eigenvectors();
  Vector extents;
  std::vector<float> along(points.size());
  for (int d = 0; d < Dims; ++d) {
    for (std::size_t i = 0; i < points.size(); ++i) along[i] = axes.col(d).dot(points[i] - mean);
    extents[d] = trimmedSpan(along, kTrim);
  }
  return extents;
}

/// How much more a camera's depth noise spreads at `points` than at the table's median distance
/// (the square of the distances' ratio, at least 1); 1 but for one camera's view.
float noiseGrowth(const Cloud& cloud, const std::vector<int>& points, const PreprocessedScene& prepared) {
  if (!(prepared.table_range > 0.0f) || points.empty()) return 1.0f;
  std::vector<float> ranges;
  ranges.reserve(points.size());
  for (int i : points) ranges.push_back((cloud[i].getVector3fMap() - prepared.viewpoint).norm());
  const float ratio = quantileOf(ranges, 0.5f) / prepared.table_range;
  return std::isfinite(ratio) ? std::clamp(ratio * ratio, 1.0f, kMaxNoiseGrowth) : 1.0f;
}

}  // namespace

Eigen::Vector3f segmentExtents(const Cloud& cloud, const std::vector<int>& points, const std::optional<Eigen::Vector3f>& up) {
  if (points.empty()) return Eigen::Vector3f::Zero();
  Eigen::Vector3f extents;
  if (up) {
    const Eigen::Vector3f normal = up->normalized();
    const Eigen::Vector3f u = normal.unitOrthogonal();
    const Eigen::Vector3f v = normal.cross(u);
    std::vector<Eigen::Vector2f> footprint;
    footprint.reserve(points.size());
    std::vector<float> heights;
    heights.reserve(points.size());
    for (int i : points) {
      const Eigen::Vector3f p = cloud[i].getVector3fMap();
      footprint.emplace_back(u.dot(p), v.dot(p));
      heights.push_back(normal.dot(p));
    }
    extents << principalExtents<2>(footprint), trimmedSpan(heights, kTrim);
  } else {
    std::vector<Eigen::Vector3f> all;
    all.reserve(points.size());
    for (int i : points) all.push_back(cloud[i].getVector3fMap());
    extents = principalExtents<3>(all);
  }
  std::sort(extents.data(), extents.data() + 3, std::greater<float>());
  return extents;
}

bool hasObjectSize(const Cloud::ConstPtr& cloud, const std::vector<int>& points, const std::optional<Eigen::Vector3f>& up,
                   const ObjectSizeParams& params, float plane_distance) {
  if (points.size() < 3) return true;
  if (params.max_extent > 0.0f && segmentExtents(*cloud, points, up)[0] > params.max_extent) return false;
  if (params.max_plane_extent <= 0.0f) return true;
  // Mostly one plane: the largest plane's share of the points, and how wide that plane is.
  const std::vector<int> on_plane = largestPlanePoints(cloud, points, plane_distance);
  if (static_cast<float>(on_plane.size()) < params.min_plane_share * static_cast<float>(points.size())) return true;
  return segmentExtents(*cloud, on_plane, std::nullopt)[0] <= params.max_plane_extent;
}

std::vector<int> largestPlanePoints(const Cloud::ConstPtr& cloud, const std::vector<int>& points, float distance) {
  if (points.size() < 3) return {};
  pcl::SACSegmentation<PointT> ransac;
  ransac.setModelType(pcl::SACMODEL_PLANE);
  ransac.setMethodType(pcl::SAC_RANSAC);
  ransac.setDistanceThreshold(distance);
  ransac.setMaxIterations(kPlaneIterations);
  ransac.setInputCloud(cloud);
  ransac.setIndices(std::make_shared<pcl::Indices>(points.begin(), points.end()));
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coefficients;
  ransac.segment(inliers, coefficients);
  return std::vector<int>(inliers.indices.begin(), inliers.indices.end());
}

TableSightings::TableSightings(const Cloud& input, const TableTop& table, float band, float cell)
    : grid_(table, cell) {
  for (const PointT& point : input) {
    if (!isUsablePoint(point)) continue;
    const Eigen::Vector3f p = point.getVector3fMap();
    const float height = grid_.height(p);
    if (std::abs(height) <= band) seen_.insert(TableGrid::key(grid_.cellOf(p)));
  }
}

std::optional<float> TableSightings::seenShareUnder(const Cloud& cloud, const std::vector<int>& points) const {
  std::unordered_set<std::int64_t> footprint;
  std::vector<TableGrid::Cell> cells;
  for (int i : points) {
    const TableGrid::Cell cell = grid_.cellOf(cloud[i].getVector3fMap());
    if (footprint.insert(TableGrid::key(cell)).second) cells.push_back(cell);
  }
  std::size_t inner = 0, seen = 0;
  for (const auto& [x, y] : cells) {
    bool surrounded = true;
    for (std::int64_t dx = -1; dx <= 1 && surrounded; ++dx) {
      for (std::int64_t dy = -1; dy <= 1 && surrounded; ++dy) surrounded = footprint.count(TableGrid::key(x + dx, y + dy)) > 0;
    }
    if (!surrounded) continue;
    ++inner;
    if (seen_.count(TableGrid::key(x, y)) > 0) ++seen;
  }
  if (inner == 0) return std::nullopt;
  return static_cast<float>(seen) / static_cast<float>(inner);
}

float topHeight(const Cloud& cloud, const std::vector<int>& points, const TableTop& table) {
  if (points.empty()) return 0.0f;
  std::vector<float> heights;
  heights.reserve(points.size());
  for (int i : points) heights.push_back(table.height(cloud[i].getVector3fMap()));
  return quantileOf(heights, 1.0f - kTrim);
}

void ObjectSizeStage::run(PipelineState& state) const {
  const float plane_distance = onPlaneDistance(voxel_size_);
  const std::size_t before = state.segments.size();
  const bool check_top = params_.min_top_height > 0.0f && state.prepared.has_table;
  const TableTop table_top = state.prepared.tableTop();
  // Made when first asked.
  std::optional<TableSightings> table_seen;
  const auto tableSeen = [&]() -> const TableSightings& {
    if (!table_seen) table_seen.emplace(*state.scene->cloud, table_top, state.prepared.table_margin, voxel_size_);
    return *table_seen;
  };
  std::size_t thin_kept = 0;
  const auto tableScrap = [&](const CandidateSegment& segment) {
    const float top = topHeight(*state.cloud, segment.points, table_top);
    if (top >= params_.min_top_height * noiseGrowth(*state.cloud, segment.points, state.prepared)) return false;
    // Without the input cloud nothing tells a scrap from a thin object: the height decides. So
    // it does for a top under two margins (6 sigma of the table's noise): the table's own
    // surface raised by a few millimetres (a cloth, a warp) hides "the table" too.
    if (state.scene == nullptr || !state.scene->cloud || top < kTableBandMargins * state.prepared.table_margin) {
      return true;
    }
    // A footprint with no inner cell hides nothing.
    if (tableSeen().seenShareUnder(*state.cloud, segment.points).value_or(1.0f) >= params_.max_table_seen_share) {
      return true;
    }
    ++thin_kept;
    return false;
  };
  // The table's specks go before any test: they neither make a segment large nor its top high.
  // A low piece that hides the table stays, as a thin object's segment does (a book beside a
  // box the cut joined to it). The segment's scores stay the cut's.
  std::size_t specks = 0;
  const std::function<bool(const std::vector<int>&)> hidesTheTable = [&](const std::vector<int>& piece) {
    if (state.scene == nullptr || !state.scene->cloud) return false;
    return tableSeen().seenShareUnder(*state.cloud, piece).value_or(1.0f) < params_.max_table_seen_share;
  };
  if (check_top && state.graph) {
    for (CandidateSegment& segment : state.segments) {
      const float scrap_height = params_.min_top_height * noiseGrowth(*state.cloud, segment.points, state.prepared);
      std::vector<int> kept = withoutTableSpecks(*state.cloud, state.graph->neighbours(), segment.points,
                                                 table_top, kPieceLinkVoxels * voxel_size_,
                                                 scrap_height, hidesTheTable);
      specks += segment.points.size() - kept.size();
      // Mostly specks, the segment was the table's noise with a scrap of something on it.
      if (2 * kept.size() < segment.points.size()) kept.clear();
      segment.points = std::move(kept);
    }
  }
  const bool check_hanging = (params_.min_table_seen_under_raised > 0.0f || params_.min_free_under_raised > 0.0f) &&
                             state.prepared.has_table &&
                             state.scene != nullptr && state.scene->cloud;
  std::size_t hanging = 0;
  const auto hangs = [&](const CandidateSegment& segment) {
    if (!restsOnNothing(*state.cloud, segment.points, table_top, state.prepared.table_margin,
                        voxel_size_)) {
      return false;
    }
    // Under an object seen over another in front of it the table is hidden, and so is the space
    // over the table; under a shelf the table is seen, or the space under it seen empty.
    bool result = false;
    if (params_.min_table_seen_under_raised > 0.0f) {
      const std::optional<float> seen = tableSeen().seenShareUnder(*state.cloud, segment.points);
      result = seen && *seen >= params_.min_table_seen_under_raised;
    }
    if (!result && params_.min_free_under_raised > 0.0f && state.occupancy) {
      const std::optional<float> free = freeShareUnder(*state.cloud, segment.points, table_top,
                                                       state.prepared.table_margin, *state.occupancy);
      result = free && *free >= params_.min_free_under_raised;
    }
    hanging += result ? 1 : 0;
    return result;
  };
  const bool check_rising = params_.min_seen_below_share > 0.0f && state.prepared.has_table &&
                            state.prepared.support_polygon && state.scene != nullptr && state.scene->cloud;
  std::optional<BelowTableSightings> below;  // made when first asked
  std::size_t rising = 0;
  const auto rises = [&](const CandidateSegment& segment) {
    if (!below) below.emplace(*state.scene->cloud, table_top);
    const bool result =
        risesFromBelowTable(*state.cloud, segment.points, table_top, state.prepared.table_margin,
                            *state.prepared.support_polygon, *below, params_.min_seen_below_share);
    rising += result ? 1 : 0;
    return result;
  };
  state.segments.erase(std::remove_if(state.segments.begin(), state.segments.end(),
                                      [&](const CandidateSegment& segment) {
                                        if (segment.points.empty()) return true;
                                        if (check_top && tableScrap(segment)) return true;
                                        if (!hasObjectSize(state.cloud, segment.points, state.up, params_, plane_distance)) return true;
                                        if (check_rising && rises(segment)) return true;
                                        return check_hanging && hangs(segment);
                                      }),
                       state.segments.end());
  state.count("rising", rising);
  state.count("speck_points", specks);
  state.count("thin_kept", thin_kept);
  state.count("hanging", hanging);
  state.count("dropped", before - state.segments.size());
}

}  // namespace symmetry_segmentation
