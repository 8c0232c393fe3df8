#include "symmetry_segmentation/occupancy_grid.h"

#include <algorithm>
#include <cmath>

#include <octomap/OcTree.h>

namespace symmetry_segmentation {

OccupancyGrid::OccupancyGrid(const OccupancyMap& map, const Eigen::AlignedBox3f& box, std::size_t max_cells)
    : map_(map) {
  if (!map.tree()) return;  // a depth image answers a query as fast as a grid would
  if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite()) return;
  const octomap::OcTree& tree = *map.tree();
  octomap::OcTreeKey low, high;
  if (!tree.coordToKeyChecked(octomap::point3d(box.min().x(), box.min().y(), box.min().z()), low) ||
      !tree.coordToKeyChecked(octomap::point3d(box.max().x(), box.max().y(), box.max().z()), high)) {
    return;  // beyond the octree's range: the map answers every query
  }
  for (int axis = 0; axis < 3; ++axis) dims_[axis] = static_cast<int>(high[axis]) - static_cast<int>(low[axis]) + 1;
  const double cells = static_cast<double>(dims_.x()) * dims_.y() * dims_.z();
  if (cells > static_cast<double>(max_cells)) {
    dims_.setZero();
    return;
  }
  min_key_ = low;
  cells_.assign(static_cast<std::size_t>(cells), Occupancy::Unknown);

  // Every leaf inside the box paints the voxels it covers (a coarse free leaf covers many).
  const double resolution = tree.getResolution();
  const octomap::point3d bbx_min(box.min().x(), box.min().y(), box.min().z());
  const octomap::point3d bbx_max(box.max().x(), box.max().y(), box.max().z());
  for (auto leaf = tree.begin_leafs_bbx(bbx_min, bbx_max), end = tree.end_leafs_bbx(); leaf != end; ++leaf) {
    const Occupancy value = tree.isNodeOccupied(*leaf) ? Occupancy::Occupied : Occupancy::Free;
    const double size = leaf.getSize();
    const int span = std::max(1, static_cast<int>(std::lround(size / resolution)));
    const octomap::point3d corner = leaf.getCoordinate() - octomap::point3d(0.5 * size, 0.5 * size, 0.5 * size);
    octomap::OcTreeKey first;
    const double half = 0.5 * resolution;
    if (!tree.coordToKeyChecked(corner + octomap::point3d(half, half, half), first)) continue;
    // Only the part of the leaf inside the box (a free leaf can be metres wide).
    int from[3], to[3];
    bool inside = true;
    for (int axis = 0; axis < 3; ++axis) {
      from[axis] = std::max(0, static_cast<int>(first[axis]) - static_cast<int>(min_key_[axis]));
      to[axis] = std::min(dims_[axis] - 1, static_cast<int>(first[axis]) + span - 1 - static_cast<int>(min_key_[axis]));
      inside = inside && from[axis] <= to[axis];
    }
    if (!inside) continue;
    for (int z = from[2]; z <= to[2]; ++z) {
      for (int y = from[1]; y <= to[1]; ++y) {
        const std::size_t row = (static_cast<std::size_t>(z) * dims_.y() + y) * dims_.x();
        std::fill(cells_.begin() + row + from[0], cells_.begin() + row + to[0] + 1, value);
      }
    }
  }
}

bool OccupancyGrid::cellIndex(const octomap::OcTreeKey& key, std::size_t& index) const {
  const int x = static_cast<int>(key[0]) - static_cast<int>(min_key_[0]);
  const int y = static_cast<int>(key[1]) - static_cast<int>(min_key_[1]);
  const int z = static_cast<int>(key[2]) - static_cast<int>(min_key_[2]);
  if (x < 0 || y < 0 || z < 0 || x >= dims_.x() || y >= dims_.y() || z >= dims_.z()) return false;
  index = (static_cast<std::size_t>(z) * dims_.y() + y) * dims_.x() + x;
  return true;
}

Occupancy OccupancyGrid::classify(const Eigen::Vector3f& point) const {
  if (cells_.empty() || !point.allFinite()) return map_.classify(point);
  octomap::OcTreeKey key;
  std::size_t index;
  if (map_.tree()->coordToKeyChecked(octomap::point3d(point.x(), point.y(), point.z()), key) && cellIndex(key, index)) {
    return cells_[index];
  }
  return map_.classify(point);
}

}  // namespace symmetry_segmentation
