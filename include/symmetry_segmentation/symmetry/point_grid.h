#pragma once
// Uniform grid over a cloud's points for fixed-radius queries. Reflection queries (up to dbuf =
// 3 cm) are the hot loop of the graph cut; a dense grid answers them several times faster than
// a kd-tree query, which pays per-call overhead (FLANN opens an OpenMP region per query).

#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

class PointGrid {
 public:
  PointGrid() = default;
  /// Non-finite points are left out. `cell_size` > 0 (grown if the grid would be huge).
  PointGrid(const Cloud& cloud, float cell_size);

  /// Calls visit(index, squared_distance) for every point within `radius` of `query`.
  /// Const and thread-safe.
  template <typename Visit>
  void forEachWithin(const Eigen::Vector3f& query, float radius, Visit&& visit) const;

 private:
  Eigen::Vector3i cellOf(const Eigen::Vector3f& point) const;
  int cellIndex(const Eigen::Vector3i& cell) const { return (cell.z() * dims_.y() + cell.y()) * dims_.x() + cell.x(); }

  float cell_size_ = 1.0f;
  Eigen::Vector3f origin_ = Eigen::Vector3f::Zero();
  Eigen::Vector3i dims_ = Eigen::Vector3i::Zero();
  std::vector<int> cell_start_;              ///< Points of cell c: entries [cell_start_[c], cell_start_[c+1]).
  std::vector<int> point_index_;             ///< Cloud indices, grouped by cell.
  std::vector<Eigen::Vector3f> positions_;   ///< Same order as point_index_ (cache-friendly scans).
};

template <typename Visit>
void PointGrid::forEachWithin(const Eigen::Vector3f& query, float radius, Visit&& visit) const {
  if (point_index_.empty() || !query.allFinite()) return;
  const Eigen::Vector3i low = cellOf(query - Eigen::Vector3f::Constant(radius)).cwiseMax(0);
  const Eigen::Vector3i high = cellOf(query + Eigen::Vector3f::Constant(radius)).cwiseMin(dims_ - Eigen::Vector3i::Ones());
  const float squared_radius = radius * radius;
  for (int z = low.z(); z <= high.z(); ++z) {
    for (int y = low.y(); y <= high.y(); ++y) {
      for (int x = low.x(); x <= high.x(); ++x) {
        const int cell = cellIndex({x, y, z});
        for (int k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
          const float squared = (positions_[k] - query).squaredNorm();
          if (squared <= squared_radius) visit(point_index_[k], squared);
        }
      }
    }
  }
}

}  // namespace symmetry_segmentation
