#pragma once
// Heights over the table and square cells on it: where a point lies seen from above. Shared by
// the tests that ask what lies over or under a segment's footprint.

#include <cmath>
#include <cstdint>
#include <utility>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

class TableGrid {
 public:
  using Cell = std::pair<std::int64_t, std::int64_t>;

  /// `table_plane` need not have a unit normal; `cell` > 0 (m).
  TableGrid(const PlaneCoefficients& table_plane, float cell)
      : up_(table_plane.head<3>().normalized()),
        offset_(table_plane[3] / table_plane.head<3>().norm()),
        e1_(up_.unitOrthogonal()),
        e2_(up_.cross(e1_)),
        cell_(cell) {}

  /// Signed height over the table (m).
  float height(const Eigen::Vector3f& p) const { return up_.dot(p) + offset_; }
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
};

}  // namespace symmetry_segmentation
