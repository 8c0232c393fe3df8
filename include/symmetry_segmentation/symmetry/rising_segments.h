#pragma once
// What rises from below the table past its edge is no tabletop object. A chair pushed in to
// the table's end, a carton or a bin on the floor beside it shows its top over the table's plane,
// inside the support polygon's margin (kept there for objects at the table's edge), and a piece
// of it is as symmetric as any object. An object stands over the table, and the table hides what
// is under its top from a sensor over it; the chair's back is beside the table and is seen to
// run on below the table's top. So a segment mostly beyond the table's own points, with a surface
// seen a few centimetres under the table's top right under most of its lowest points, is dropped
// (object_size). A fused map that never saw under the table (kinfu) has nothing there to see.

#include <cstdint>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/support_polygon.h"
#include "symmetry_segmentation/table_grid.h"

namespace symmetry_segmentation {

/// Where a surface was seen 3-6 cm under the table's top: 1.5 cm cells of a grid on the table's
/// plane over which `input` has points that deep.
class BelowTableSightings {
 public:
  BelowTableSightings(const Cloud& input, const TableTop& table);
  /// Whether such a surface lies under `point`: in its cell or one next to it.
  bool seenUnder(const Eigen::Vector3f& point) const;

 private:
  TableGrid grid_;
  std::unordered_set<std::int64_t> seen_;
};

/// Whether `points` of `cloud` rise from below the table past its edge (see above): a quarter of
/// them at least lie beyond `support`'s table points (not SupportPolygon::overTable), and of their
/// points within 2 cm over `table_margin` (at least 5), `min_seen_below_share` at least have a
/// surface of `below` under them. Never with `min_seen_below_share` 0.
bool risesFromBelowTable(const Cloud& cloud, const std::vector<int>& points, const TableTop& table,
                         float table_margin, const SupportPolygon& support, const BelowTableSightings& below,
                         float min_seen_below_share);

}  // namespace symmetry_segmentation
