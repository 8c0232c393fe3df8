// Segments that rest on nothing (see the header for why).
#include "symmetry_segmentation/symmetry/hanging_segments.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <unordered_set>

#include "symmetry_segmentation/occupancy.h"
#include "symmetry_segmentation/point_validity.h"
#include "symmetry_segmentation/raised_off_table.h"
#include "symmetry_segmentation/table_grid.h"

namespace symmetry_segmentation {
namespace {

// A gap of fewer cells over the table margin is no gap.
constexpr float kMinGapCells = 3.0f;
// A point of anything else from one to this many cells under the base, over the footprint, may
// be what the segment rests on.
constexpr float kHoldingCells = 5.0f;
// Probes under a segment: clear of the table's noise and of the segment's own base (m), this far
// apart up the column.
constexpr float kProbeClearance = 0.02f;
constexpr float kProbeStep = 0.03f;

}  // namespace

bool restsOnNothing(const Cloud& cloud, const std::vector<int>& points, const TableTop& table,
                    float table_margin, float cell) {
  if (!(table.plane.head<3>().norm() > 0.0f) || !(cell > 0.0f)) return false;
  const TableGrid grid(table, cell);
  std::vector<int> usable;  // sorted, for the membership test below
  std::vector<float> heights;
  for (int i : points) {
    if (i < 0 || static_cast<std::size_t>(i) >= cloud.size() || !isUsablePoint(cloud[i])) continue;
    usable.push_back(i);
    heights.push_back(grid.height(cloud[i].getVector3fMap()));
  }
  const std::optional<float> base = raisedBase(heights, table_margin, kMinGapCells * cell);
  if (!base) return false;

  // Anything else under the footprint (grown by a cell), just below the base, may hold it up.
  std::sort(usable.begin(), usable.end());
  std::unordered_set<std::int64_t> footprint;
  for (int i : usable) {
    const auto [x, y] = grid.cellOf(cloud[i].getVector3fMap());
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) footprint.insert(TableGrid::key(x + dx, y + dy));
    }
  }
  for (std::size_t j = 0; j < cloud.size(); ++j) {
    if (!isUsablePoint(cloud[j])) continue;
    const Eigen::Vector3f p = cloud[j].getVector3fMap();
    const float h = grid.height(p);
    if (h < *base - kHoldingCells * cell || h > *base - cell) continue;
    if (footprint.count(TableGrid::key(grid.cellOf(p))) == 0) continue;
    if (!std::binary_search(usable.begin(), usable.end(), static_cast<int>(j))) return false;
  }
  return true;
}

std::optional<float> freeShareUnder(const Cloud& cloud, const std::vector<int>& points,
                                    const TableTop& table, float table_margin,
                                    const OccupancyMap& occupancy) {
  if (!(table.plane.head<3>().norm() > 0.0f)) return std::nullopt;
  const TableGrid grid(table, 1.0f);
  const Eigen::Vector3f& up = grid.up();
  std::vector<int> usable;
  std::vector<float> heights;
  for (int i : points) {
    if (i < 0 || static_cast<std::size_t>(i) >= cloud.size() || !isUsablePoint(cloud[i])) continue;
    usable.push_back(i);
    heights.push_back(grid.height(cloud[i].getVector3fMap()));
  }
  if (usable.empty()) return std::nullopt;
  std::vector<float> reordered = heights;  // segmentBase reorders what it is given
  const float top = segmentBase(reordered) - kProbeClearance;
  std::size_t probes = 0, free = 0;
  for (std::size_t k = 0; k < usable.size(); ++k) {
    const Eigen::Vector3f p = cloud[usable[k]].getVector3fMap();
    for (float z = table_margin + kProbeClearance; z < top; z += kProbeStep) {
      ++probes;
      free += occupancy.classify(p - (heights[k] - z) * up) == Occupancy::Free ? 1 : 0;
    }
  }
  if (probes == 0) return std::nullopt;
  return static_cast<float>(free) / static_cast<float>(probes);
}

}  // namespace symmetry_segmentation
