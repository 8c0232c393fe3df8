// Segments that rise from below the table past its edge (see the header for why).
#include "symmetry_segmentation/symmetry/rising_segments.h"

#include "symmetry_segmentation/point_validity.h"

namespace symmetry_segmentation {
namespace {

// Cells of the grid the sightings are kept on (m): a point's own and its eight neighbours reach
// 1.5-3 cm across the plane, a chair's back 2 cm past the table's end and the back itself.
constexpr float kCell = 0.015f;
// A segment's lowest points: within this over the table margin (m).
constexpr float kLowBand = 0.02f;
constexpr std::size_t kMinLowPoints = 5;
// Of a segment, this share at least lies beyond the table's own points: an object stands over
// the table; a chair's back pushed in to the table's end is 40-66 % beyond it (seeds 17-20),
// and a surface it is seen under may still be a table's edge. (The table's
// points leave out a strip 1.5 cm wide along an edge seen 3 cm deep or more, support_polygon.h:
// a box within 2 cm of such an edge can go. Requiring a surface seen deeper still, where a
// table's edge has ended, spares it but misses most chairs' backs, hidden there by the table.)
constexpr float kMinBeyondShare = 0.25f;

}  // namespace

BelowTableSightings::BelowTableSightings(const Cloud& input, const TableTop& table)
    : grid_(table, kCell) {
  for (const PointT& point : input) {
    if (!isUsablePoint(point)) continue;
    const Eigen::Vector3f p = point.getVector3fMap();
    const float height = grid_.height(p);
    if (height <= -kSeenUnderTopMin && height >= -kSeenUnderTopMax) seen_.insert(TableGrid::key(grid_.cellOf(p)));
  }
}

bool BelowTableSightings::seenUnder(const Eigen::Vector3f& point) const {
  const auto [x, y] = grid_.cellOf(point);
  const auto near = [&, x = x, y = y](const std::unordered_set<std::int64_t>& cells) {
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        if (cells.count(TableGrid::key(x + dx, y + dy)) > 0) return true;
      }
    }
    return false;
  };
  return !seen_.empty() && near(seen_);
}

bool risesFromBelowTable(const Cloud& cloud, const std::vector<int>& points, const TableTop& table,
                         float table_margin, const SupportPolygon& support, const BelowTableSightings& below,
                         float min_seen_below_share) {
  if (!(table.plane.head<3>().norm() > 0.0f) || !(min_seen_below_share > 0.0f)) return false;
  const TableGrid grid(table, 1.0f);
  std::size_t usable = 0, beyond = 0, low = 0, low_over_below = 0;
  for (int i : points) {
    if (i < 0 || static_cast<std::size_t>(i) >= cloud.size() || !isUsablePoint(cloud[i])) continue;
    const Eigen::Vector3f p = cloud[i].getVector3fMap();
    ++usable;
    beyond += support.overTable(p) ? 0 : 1;
    if (grid.height(p) > table_margin + kLowBand) continue;
    ++low;
    low_over_below += below.seenUnder(p) ? 1 : 0;
  }
  if (usable == 0 || low < kMinLowPoints) return false;
  return static_cast<float>(beyond) >= kMinBeyondShare * static_cast<float>(usable) &&
         static_cast<float>(low_over_below) >= min_seen_below_share * static_cast<float>(low);
}

}  // namespace symmetry_segmentation
