#pragma once
// The table's top as a gently curved surface over its plane: a quadratic height field fitted to
// the median heights of the table's points in square cells. A fused map's table drifts by some
// millimetres across the scene and a far table seen by a single camera bends away from the plane
// fitted to its near part; a cut at one height over one plane then takes the bottom centimetre
// of some objects and leaves table under others, and which ones turns on millimetres of the
// plane's offset. Heights measured from the surface follow the table instead.

#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

class TableSurface {
 public:
  /// Fits the surface to the points of `cloud` at `indices` within `band` of `plane` (normal up,
  /// not necessarily unit); with `facing_up`, only points whose normal is within ~37 deg of the
  /// plane's (when enough have one). Cells of `cell` m; a cell's median height is one sample and
  /// cells far off the others' surface (a board lying on the table) are left out. None when too
  /// few cells tell a surface.
  static std::optional<TableSurface> fit(const Cloud& cloud, const std::vector<int>& indices,
                                         const PlaneCoefficients& plane, float band, bool facing_up, float cell);

  /// Signed height of `p` over the surface (m).
  float height(const Eigen::Vector3f& p) const;
  /// The surface's height over the plane at `p`'s place on it (m).
  float lift(const Eigen::Vector3f& p) const;
  /// The largest |lift| over the cells the fit used (m): how far the table bends from its plane.
  float maxLift() const { return max_lift_; }
  std::size_t cells() const { return cells_; }
  /// The plane through the table cells the fit kept (unit normal, up).
  const PlaneCoefficients& plane() const { return plane_; }

 private:
  TableSurface(const PlaneCoefficients& plane, const Eigen::Vector3f& origin);
  Eigen::Vector<float, 6> terms(const Eigen::Vector3f& p) const;

  Eigen::Vector3f up_, e1_, e2_, origin_;
  float offset_ = 0.0f;
  float scale_ = 1.0f;  ///< Plane coordinates are divided by it, to keep the quadratic well scaled.
  Eigen::Vector<float, 6> coefficients_ = Eigen::Vector<float, 6>::Zero();
  float max_lift_ = 0.0f;
  std::size_t cells_ = 0;
  PlaneCoefficients plane_ = PlaneCoefficients::Zero();
};

/// Signed height of `p` over `surface` if fitted, else over `plane` (normal up; m).
inline float tableTopHeight(const PlaneCoefficients& plane, const std::optional<TableSurface>& surface,
                            const Eigen::Vector3f& p) {
  if (surface) return surface->height(p);
  return (plane.head<3>().dot(p) + plane[3]) / plane.head<3>().norm();
}

/// Where heights are measured from: the table's plane (normal up), and the surface over it when
/// one was fitted.
struct TableTop {
  TableTop(const PlaneCoefficients& table_plane, std::optional<TableSurface> table_surface = std::nullopt)
      : plane(table_plane), surface(std::move(table_surface)) {}
  /// Signed height of `p` over the surface if fitted, else over the plane (m).
  float height(const Eigen::Vector3f& p) const { return tableTopHeight(plane, surface, p); }
  PlaneCoefficients plane;
  std::optional<TableSurface> surface;
};

}  // namespace symmetry_segmentation
