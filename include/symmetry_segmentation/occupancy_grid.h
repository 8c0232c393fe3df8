#pragma once
// A dense copy of an OccupancyMap over a box, for the hot loops that classify millions of
// reflected points: an octree search per query costs a tree walk, a grid cell one index. Same
// answers as the map (cells are the map's own voxels); queries outside the box ask the map.
// A map made from a depth image is not copied: it answers a query as fast as a cell would.

#include <vector>

#include <Eigen/Geometry>
#include <octomap/OcTreeKey.h>

#include "symmetry_segmentation/occupancy.h"

namespace symmetry_segmentation {

class OccupancyGrid {
 public:
  /// Caches `map` over `box`; a box of more than `max_cells` voxels is not cached (every query
  /// then asks the map). `map` must outlive this object.
  OccupancyGrid(const OccupancyMap& map, const Eigen::AlignedBox3f& box, std::size_t max_cells = 64u << 20);

  /// Same as OccupancyMap::classify. Const and thread-safe.
  Occupancy classify(const Eigen::Vector3f& point) const;

  std::size_t cachedCells() const { return cells_.size(); }

 private:
  bool cellIndex(const octomap::OcTreeKey& key, std::size_t& index) const;

  const OccupancyMap& map_;
  octomap::OcTreeKey min_key_;
  Eigen::Vector3i dims_ = Eigen::Vector3i::Zero();
  std::vector<Occupancy> cells_;
};

}  // namespace symmetry_segmentation
