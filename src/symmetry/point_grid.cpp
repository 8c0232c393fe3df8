// Dense uniform grid (counting sort of points into cells) for fixed-radius queries.
#include "symmetry_segmentation/symmetry/point_grid.h"

#include <cmath>

#include <Eigen/Geometry>

namespace symmetry_segmentation {
namespace {

/// Fixed: cap on the number of cells, so a stray far point cannot make the grid huge (memory).
constexpr double kMaxCells = 4.0e6;

}  // namespace

PointGrid::PointGrid(const Cloud& cloud, float cell_size) : cell_size_(cell_size) {
  Eigen::AlignedBox3f box;
  for (const auto& point : cloud.points) {
    if (point.getVector3fMap().allFinite()) box.extend(point.getVector3fMap());
  }
  if (box.isEmpty()) return;
  const Eigen::Vector3f extent = box.sizes();
  auto cellsFor = [&](float size) {
    return ((extent / size).array().floor() + 1.0f).cast<double>().prod();
  };
  while (cellsFor(cell_size_) > kMaxCells) cell_size_ *= 2.0f;
  origin_ = box.min();
  dims_ = ((extent / cell_size_).array().floor() + 1.0f).cast<int>();

  const int cells = dims_.prod();
  std::vector<int> cell_of_point(cloud.size(), -1);
  cell_start_.assign(cells + 1, 0);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!cloud.points[i].getVector3fMap().allFinite()) continue;
    cell_of_point[i] = cellIndex(cellOf(cloud.points[i].getVector3fMap()));
    ++cell_start_[cell_of_point[i] + 1];
  }
  for (int c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  point_index_.resize(cell_start_[cells]);
  positions_.resize(cell_start_[cells]);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cell_of_point[i] < 0) continue;
    const int slot = fill[cell_of_point[i]]++;
    point_index_[slot] = static_cast<int>(i);
    positions_[slot] = cloud.points[i].getVector3fMap();
  }
}

Eigen::Vector3i PointGrid::cellOf(const Eigen::Vector3f& point) const {
  // Clamp in float before converting: far queries must not overflow int.
  const Eigen::Array3f cell = ((point - origin_) / cell_size_).array().floor();
  return cell.max(-1.0f).min(dims_.cast<float>().array()).cast<int>();
}

}  // namespace symmetry_segmentation
