#pragma once
// Heights over the table's top and square cells on its plane: where a point lies seen from
// above. Shared by the tests that ask what lies over or under a segment's footprint.

#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/table_surface.h"

namespace symmetry_segmentation {

class TableGrid {
 public:
  using Cell = std::pair<std::int64_t, std::int64_t>;

  /// Cells on `table.plane` (normal up, need not be unit); heights over its surface where fitted,
  /// as every stage measures them. `cell` > 0 (m).
  TableGrid(const TableTop& table, float cell)
      : up_(table.plane.head<3>().normalized()),
        offset_(table.plane[3] / table.plane.head<3>().norm()),
        e1_(up_.unitOrthogonal()),
        e2_(up_.cross(e1_)),
        cell_(cell),
        surface_(table.surface) {}

  /// Signed height over the table's top (m).
  float height(const Eigen::Vector3f& p) const { return surface_ ? surface_->height(p) : up_.dot(p) + offset_; }
  /// The plane's unit normal.
  const Eigen::Vector3f& up() const { return up_; }
  Cell cellOf(const Eigen::Vector3f& p) const {
    return {static_cast<std::int64_t>(std::floor(e1_.dot(p) / cell_)), static_cast<std::int64_t>(std::floor(e2_.dot(p) / cell_))};
  }
  /// One key per cell, for hash sets.
  static std::int64_t key(std::int64_t x, std::int64_t y) {
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(x) << 32) ^ (y & 0xffffffff);  // no shift of a negative
  }
  static std::int64_t key(const Cell& cell) { return key(cell.first, cell.second); }

 private:
  Eigen::Vector3f up_;
  float offset_;
  Eigen::Vector3f e1_, e2_;
  float cell_;
  std::optional<TableSurface> surface_;
};

}  // namespace symmetry_segmentation
