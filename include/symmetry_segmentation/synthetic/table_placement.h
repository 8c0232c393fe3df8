#pragma once
// Random placement of objects on the table top without interpenetration, using their convex
// footprints. Groups of objects (a row of flush boxes, a stack) are placed rigidly together.

#include <cmath>
#include <vector>

#include "symmetry_segmentation/synthetic/footprint.h"
#include "symmetry_segmentation/synthetic/random.h"
#include "symmetry_segmentation/synthetic/synthetic_object.h"

namespace symmetry_segmentation {
namespace synthetic {

struct TableRegion {
  Eigen::Vector2d min{-0.35, -0.22};
  Eigen::Vector2d max{0.35, 0.22};
};

class TablePlacer {
 public:
  /// `limit` bounds how far the region may grow when the objects do not fit.
  TablePlacer(const TableRegion& region, const TableRegion& limit, Random& random);

  /// Moves `group` (poses relative to the group's frame) to a random position and a heading
  /// within +-max_yaw at which every member keeps at least `gap` from everything placed
  /// before. Grows the region toward the limit when crowded; throws std::runtime_error if even
  /// that fails.
  void place(std::vector<SyntheticObject>& group, double gap, double max_yaw = M_PI);
  /// Same for one object.
  void place(SyntheticObject& object, double gap, double max_yaw = M_PI);
  /// Records an object placed by hand, so later objects keep clear of it.
  void reserve(const SyntheticObject& object);

 private:
  bool fits(const std::vector<Footprint>& footprints, double gap) const;

  TableRegion region_;
  TableRegion limit_;
  Random& random_;
  std::vector<Footprint> placed_;
};

}  // namespace synthetic
}  // namespace symmetry_segmentation
