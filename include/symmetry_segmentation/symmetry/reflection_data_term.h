#pragma once
// Paper eq. 7-10, as we read them: what the reflection of one point about a candidate plane says
// about the point belonging to the object symmetric about that plane.
//
//   p' = reflectPoint(plane, p), n' = reflectDirection(plane, n_p), q = nearest scene point of p',
//   r = |q - p'| (searched up to dbuf, where the penalty saturates), alpha = angle(n', n_q) in degrees (normals are oriented: 0..180).
//   * r <= dmax ("lands on a point"): w = 1 for alpha <= alpha_min, 0 for alpha >= alpha_max,
//     linear between; cost(FG) = 1 - w, cost(BG) = w. Of the scene points within dmax of p'
//     q is the one with the largest w (ties: the nearest), so that thin walls, whose
//     inner and outer voxels lie side by side, still match. A point on the plane
//     (|p' - p| < dmax) is a candidate counterpart of itself.
//     A candidate q is skipped when the mirrored element faces away from it and lies behind it,
//     n' . n_q < 0 and (p' - q) . n_q < 0: that is the hidden side of a thin wall (see below).
//   * else, p' more than dbuf below the table plane: an object's mirror image is the object, which
//     stands above the table, so this is background: cost(FG) = 1, cost(BG) = 0.
//   * else, p' up to dbuf below the table, on the hidden side of a surface (skipped candidate),
//     in unknown / occupied space, or in free space within dmax of unknown / occupied space
//     behind the mirrored surface (p' - dmax n' not free: the hidden back face of the object,
//     displaced by noise and the voxel grid) ("occluded"): no evidence either way,
//     cost(FG) = cost(BG) = 0; smoothness decides.
//   * else (observed free space): cost(FG) = clamp((r - dmax) / (dbuf - dmax), 0, 1), cost(BG) = 0.
//     With unobserved_steps > 0, r is the distance to the nearest scene point or unobserved /
//     occupied cell, whichever is nearer (probed in the 26 grid directions at 1..steps x dmax):
//     unobserved space may hold the surface the reflection stands for (the authors' obstacle
//     distance, aecins/symseg).

#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "symmetry_segmentation/occupancy_grid.h"
#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/segmentation_result.h"
#include "symmetry_segmentation/symmetry/point_grid.h"
#include "symmetry_segmentation/table_surface.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace symmetry_segmentation {

enum class ReflectionLanding : unsigned char {
  OnPoint,   ///< Within dmax of a scene point: the normals decide.
  Occluded,  ///< Unknown or occupied space, just below the table, behind a thin wall: no evidence.
  Free       ///< Observed free space, or deep below the table: evidence against.
};

struct ReflectionEvidence {
  ReflectionLanding landing = ReflectionLanding::Free;
  int match = -1;                    ///< Scene point the reflection lands on (OnPoint only).
  float distance = 0.0f;             ///< |q - p'| (m), capped at dbuf; 0 when occluded.
  float foreground_strength = 0.0f;  ///< w in [0, 1] (OnPoint only, else 0).
  float cost_foreground = 0.0f;
  float cost_background = 0.0f;
};

/// Angle between two unit directions in degrees (0..180).
float angleDeg(const Eigen::Vector3f& a, const Eigen::Vector3f& b);

/// Foreground strength w of a match whose normals differ by `alpha_deg`.
float normalCompatibility(float alpha_deg, const SymmetryCutParams& params);

/// Cost of foreground for a reflection `distance` from the nearest surface point in free space.
float freeSpaceCost(float distance, const SymmetryCutParams& params);

/// A short-lived view over one scene's data; everything referenced must outlive it.
/// evaluate() is const and thread-safe.
class ReflectionDataTerm {
 public:
  ReflectionDataTerm(const Cloud& cloud, const PointGrid& grid, const Eigen::AlignedBox3f& cloud_box,
                     const OccupancyGrid& occupancy, const std::optional<TableTop>& table,
                     const SymmetryCutParams& params);

  ReflectionEvidence evaluate(int index, const SymmetryPlane& plane) const;

 private:
  /// Signed height over the table's top (+inf without a table).
  float heightAboveTable(const Eigen::Vector3f& point) const;
  /// The first probe distance (1..unobserved_steps x dmax, below `limit`) at which a grid
  /// direction from `point` meets space that is not free; `limit` if none does.
  float unobservedWithin(const Eigen::Vector3f& point, float limit) const;

  const Cloud& cloud_;
  const PointGrid& grid_;
  const Eigen::AlignedBox3f& cloud_box_;
  const OccupancyGrid& occupancy_;
  const std::optional<TableTop>& table_;
  const SymmetryCutParams& params_;
};

}  // namespace symmetry_segmentation
