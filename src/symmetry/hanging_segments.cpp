// Segments that rest on nothing (see the header for why).
#include "symmetry_segmentation/symmetry/hanging_segments.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_set>
#include <utility>

#include "symmetry_segmentation/raised_off_table.h"

namespace symmetry_segmentation {
namespace {

// A gap of fewer cells over the table margin is no gap.
constexpr float kMinGapCells = 3.0f;
// A point of anything else from one to this many cells under the base, over the footprint, may
// be what the segment rests on.
constexpr float kHoldingCells = 5.0f;

/// Cells of side `cell` on a grid in the plane normal to `up`.
class FootprintCells {
 public:
  FootprintCells(const Eigen::Vector3f& up, float cell) : e1_(up.unitOrthogonal()), e2_(up.cross(e1_)), cell_(cell) {}
  /// The cell of `p` and its 8 neighbours.
  void addGrown(const Eigen::Vector3f& p) {
    const auto [x, y] = cellOf(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) cells_.insert(key(x + dx, y + dy));
    }
  }
  bool contains(const Eigen::Vector3f& p) const {
    const auto [x, y] = cellOf(p);
    return cells_.count(key(x, y)) > 0;
  }

 private:
  std::pair<std::int64_t, std::int64_t> cellOf(const Eigen::Vector3f& p) const {
    return {static_cast<std::int64_t>(std::floor(e1_.dot(p) / cell_)),
            static_cast<std::int64_t>(std::floor(e2_.dot(p) / cell_))};
  }
  static std::int64_t key(std::int64_t x, std::int64_t y) {
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(x) << 32) ^ (y & 0xffffffff);  // no shift of a negative
  }

  Eigen::Vector3f e1_, e2_;
  float cell_;
  std::unordered_set<std::int64_t> cells_;
};

}  // namespace

bool restsOnNothing(const Cloud& cloud, const std::vector<int>& points, const PlaneCoefficients& table_plane,
                    float table_margin, float cell) {
  const float norm = table_plane.head<3>().norm();
  if (points.empty() || !(norm > 0.0f) || !(cell > 0.0f)) return false;
  const Eigen::Vector3f up = table_plane.head<3>() / norm;
  const float offset = table_plane[3] / norm;
  const auto height = [&](const Eigen::Vector3f& p) { return up.dot(p) + offset; };

  std::vector<float> heights;
  heights.reserve(points.size());
  for (int i : points) heights.push_back(height(cloud[i].getVector3fMap()));
  const std::optional<float> raised = raisedBase(heights, table_margin, kMinGapCells * cell);
  if (!raised) return false;
  const float base = *raised;

  FootprintCells footprint(up, cell);
  std::vector<char> inside(cloud.size(), 0);
  for (int i : points) {
    inside[i] = 1;
    footprint.addGrown(cloud[i].getVector3fMap());
  }
  for (std::size_t j = 0; j < cloud.size(); ++j) {
    if (inside[j]) continue;
    const Eigen::Vector3f p = cloud[j].getVector3fMap();
    const float h = height(p);
    if (h >= base - kHoldingCells * cell && h <= base - cell && footprint.contains(p)) return false;
  }
  return true;
}

}  // namespace symmetry_segmentation
