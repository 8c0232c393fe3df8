// Object bottoms within the table margin given back to their segments (see the header for why).
#include "symmetry_segmentation/object_bottoms.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include <pcl/kdtree/kdtree_flann.h>

#include "symmetry_segmentation/point_validity.h"

namespace symmetry_segmentation {

namespace {

/// The side points of objectBottoms (see the header).
std::vector<std::vector<int>> objectSides(const Scene& scene, const PreprocessedScene& prepared, float voxel_size,
                                          const std::vector<std::vector<int>>& segments,
                                          const ObjectBottomParams& params) {
  std::vector<std::vector<int>> added(segments.size());
  // A camera frame without normals got them from its pixel grid, the table band's too.
  const bool band_normals = !scene.has_normals && !prepared.table_band_normals.empty();
  if (!prepared.has_table || !(scene.has_normals || band_normals) || !scene.cloud || segments.empty()) return added;
  const Cloud& input = *scene.cloud;
  const Eigen::Vector3f up = prepared.table_plane.head<3>();
  const float up_norm = up.norm();
  if (!(up_norm > 0.0f)) return added;
  const float reach = params.link_distance > 0.0f ? params.link_distance : voxel_size;

  // Dropped side points: within the margin of the plane on either side (the table's noise spreads
  // both ways), normal across the table.
  auto height = [&](const PointT& p) { return prepared.tableHeight(p.getVector3fMap()); };
  auto normalOf = [&](int i) -> Eigen::Vector3f {
    if (!band_normals) return input[i].getNormalVector3fMap();
    const auto at = std::lower_bound(prepared.table_band.begin(), prepared.table_band.end(), i);
    if (at == prepared.table_band.end() || *at != i) return Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN());
    return prepared.table_band_normals[at - prepared.table_band.begin()];
  };
  std::vector<int> candidates;
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (prepared.input_to_voxel[i] >= 0) continue;
    const PointT& p = input[i];
    if (!isUsablePoint(p)) continue;
    // Outside the region of interest nothing is segmented, bottoms included.
    if (!scene.inRegionOfInterest(p.getVector3fMap())) continue;
    const float h = height(p);
    if (h < -prepared.table_margin || h > prepared.table_margin) continue;
    const Eigen::Vector3f n = normalOf(static_cast<int>(i));
    const float n_norm = n.norm();
    if (!n.allFinite() || !(n_norm > 0.0f) || std::fabs(n.dot(up)) >= params.max_side_normal_cos * n_norm * up_norm) continue;
    candidates.push_back(static_cast<int>(i));
  }
  if (candidates.empty()) return added;

  // Segment points low enough to reach a candidate, each tagged with its segment.
  auto seeds = std::make_shared<Cloud>();
  std::vector<int> seed_segment;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    for (int i : segments[s]) {
      if (i < 0 || static_cast<std::size_t>(i) >= input.size() || height(input[i]) > prepared.table_margin + reach) continue;
      seeds->push_back(input[i]);
      seed_segment.push_back(static_cast<int>(s));
    }
  }
  if (seeds->empty()) return added;
  pcl::KdTreeFLANN<PointT> seed_tree;
  seed_tree.setInputCloud(seeds);
  auto candidate_cloud = std::make_shared<Cloud>();
  for (int i : candidates) candidate_cloud->push_back(input[i]);
  pcl::KdTreeFLANN<PointT> candidate_tree;
  candidate_tree.setInputCloud(candidate_cloud);

  // Breadth first from the segments' own points, so each strip goes to the segment above it.
  std::vector<int> owner(candidates.size(), -1);
  std::vector<int> frontier;
  std::vector<int> found(1);
  std::vector<float> squared(1);
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (seed_tree.nearestKSearch(input[candidates[c]], 1, found, squared) > 0 && squared[0] <= reach * reach) {
      owner[c] = seed_segment[found[0]];
      frontier.push_back(static_cast<int>(c));
    }
  }
  // A side runs straight down under its object's lowest points; the table's noise beside it,
  // whose normals a camera frame's pixel grid turns every way, does not. Linked through such
  // points, the growth ran out across the table (generated Kinect views: 60 table points 4 cm
  // past a box's foot, its box 4 cm too deep). So a side point lies within the link distance of
  // its segment's seeds, seen from above.
  const Eigen::Vector3f unit_up = up / up_norm;
  auto seenFromAbove = [&](const PointT& p) {
    PointT flat = p;
    flat.getVector3fMap() -= unit_up.dot(p.getVector3fMap()) * unit_up;
    return flat;
  };
  auto flat_seeds = std::make_shared<Cloud>();
  for (const auto& p : seeds->points) flat_seeds->push_back(seenFromAbove(p));
  pcl::KdTreeFLANN<PointT> flat_seed_tree;
  flat_seed_tree.setInputCloud(flat_seeds);
  std::vector<int> below;
  std::vector<float> below_squared;
  auto underSegment = [&](int c, int segment) {
    flat_seed_tree.radiusSearch(seenFromAbove(input[candidates[c]]), reach, below, below_squared);
    return std::any_of(below.begin(), below.end(), [&](int j) { return seed_segment[j] == segment; });
  };
  std::vector<int> near;
  std::vector<float> near_squared;
  for (std::size_t head = 0; head < frontier.size(); ++head) {
    const int c = frontier[head];
    candidate_tree.radiusSearch(input[candidates[c]], reach, near, near_squared);
    for (int d : near) {
      if (owner[d] >= 0 || !underSegment(d, owner[c])) continue;
      owner[d] = owner[c];
      frontier.push_back(d);
    }
  }
  // Candidates are in input order, so each list comes out sorted.
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (owner[c] >= 0) added[owner[c]].push_back(candidates[c]);
  }
  return added;
}

}  // namespace

std::vector<std::vector<int>> objectBottoms(const Scene& scene, const PreprocessedScene& prepared, float voxel_size,
                                            const std::vector<std::vector<int>>& segments,
                                            const ObjectBottomParams& params) {
  std::vector<std::vector<int>> added = objectSides(scene, prepared, voxel_size, segments, params);
  if (!(params.min_floor_area > 0.0f)) return added;
  std::vector<int> taken;
  for (const auto& list : added) taken.insert(taken.end(), list.begin(), list.end());
  std::sort(taken.begin(), taken.end());
  FloorParams floor_params;
  floor_params.cell = voxel_size;
  floor_params.min_floor_area = params.min_floor_area;
  const std::vector<std::vector<int>> floors = enclosedFloors(scene, prepared, segments, taken, floor_params);
  for (std::size_t s = 0; s < added.size(); ++s) {
    if (floors[s].empty()) continue;
    std::vector<int> merged;
    merged.reserve(added[s].size() + floors[s].size());
    std::merge(added[s].begin(), added[s].end(), floors[s].begin(), floors[s].end(), std::back_inserter(merged));
    added[s].swap(merged);
  }
  return added;
}

std::size_t restoreObjectBottoms(const Scene& scene, const PreprocessedScene& prepared, float voxel_size,
                                 std::vector<Segment>& segments, const ObjectBottomParams& params) {
  std::vector<std::vector<int>> indices;
  indices.reserve(segments.size());
  for (const Segment& segment : segments) indices.push_back(segment.indices);
  const std::vector<std::vector<int>> added = objectBottoms(scene, prepared, voxel_size, indices, params);
  std::size_t count = 0;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    count += added[s].size();
    segments[s].indices.insert(segments[s].indices.end(), added[s].begin(), added[s].end());
    std::sort(segments[s].indices.begin(), segments[s].indices.end());
  }
  return count;
}

}  // namespace symmetry_segmentation
