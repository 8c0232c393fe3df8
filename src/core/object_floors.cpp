// The floor inside a hollow object given back to its segment (see the header for why).
#include "symmetry_segmentation/object_floors.h"

#include <algorithm>
#include <cmath>

#include "symmetry_segmentation/point_validity.h"
#include "symmetry_segmentation/raised_off_table.h"
#include "symmetry_segmentation/sparse_cells.h"

namespace symmetry_segmentation {
namespace {

// A footprint wider than this (m) is no graspable object's (object_size drops those over 0.5 m);
// its pockets are not looked for, which also bounds the rays' work.
constexpr float kMaxFootprintSide = 1.0f;
// A floor lies under a segment that stands on the table, not under one raised off it
// (raised_off_table.h: the gap under it wider than this many cells and than it is tall; a shelf
// over the table encloses the table seen under it all the same).
constexpr float kMinRaisedCells = 3.0f;

/// The cell of the table's grid (axes e1, e2, side `cell`) a point lies over.
std::pair<int, int> cellOf(const Eigen::Vector3f& p, const Eigen::Vector3f& e1, const Eigen::Vector3f& e2, float cell) {
  return {static_cast<int>(std::floor(p.dot(e1) / cell)), static_cast<int>(std::floor(p.dot(e2) / cell))};
}

/// A segment's footprint on the table: which cells its points fall in, and which cells lie in a
/// pocket the footprint encloses (large enough to be a floor).
class Footprint {
 public:
  /// `points`: the segment's, stray pixels left out (they would close pockets over the table).
  Footprint(const std::vector<Eigen::Vector3f>& points, const Eigen::Vector3f& e1, const Eigen::Vector3f& e2,
            const FloorParams& params)
      : params_(params) {
    if (points.empty()) return;
    std::vector<std::pair<int, int>> cells;
    cells.reserve(points.size());
    for (const Eigen::Vector3f& p : points) cells.push_back(cellOf(p, e1, e2, params_.cell));
    min_x_ = max_x_ = cells.front().first;
    min_y_ = max_y_ = cells.front().second;
    for (const auto& [x, y] : cells) {
      min_x_ = std::min(min_x_, x);
      max_x_ = std::max(max_x_, x);
      min_y_ = std::min(min_y_, y);
      max_y_ = std::max(max_y_, y);
    }
    width_ = max_x_ - min_x_ + 1;
    height_ = max_y_ - min_y_ + 1;
    const int max_cells = static_cast<int>(std::ceil(kMaxFootprintSide / params_.cell));
    if (width_ > max_cells || height_ > max_cells) {
      width_ = height_ = 0;
      return;
    }
    occupied_.assign(static_cast<std::size_t>(width_) * height_, 0);
    for (const auto& [x, y] : cells) occupied_[index(x - min_x_, y - min_y_)] = 1;
    findFloor();
  }

  bool onFloor(const std::pair<int, int>& cell) const {
    const int x = cell.first - min_x_, y = cell.second - min_y_;
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return false;
    return floor_[index(x, y)] != 0;
  }

 private:
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width_ + x; }

  /// Per cell: whether every one of 8 rays from it meets an occupied cell before leaving the
  /// box. One sweep per direction, each cell looking at the next one along the ray.
  std::vector<char> enclosedCells() const {
    static const int kSteps[8][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    std::vector<char> enclosed(occupied_.size(), 1);
    std::vector<char> hit(occupied_.size(), 0);
    for (const auto& step : kSteps) {
      // Visit the cells so that (x + dx, y + dy) comes before (x, y).
      for (int j = 0; j < height_; ++j) {
        const int y = step[1] > 0 ? height_ - 1 - j : j;
        for (int i = 0; i < width_; ++i) {
          const int x = step[0] > 0 ? width_ - 1 - i : i;
          const int nx = x + step[0], ny = y + step[1];
          const bool inside = nx >= 0 && ny >= 0 && nx < width_ && ny < height_;
          hit[index(x, y)] = inside && (occupied_[index(nx, ny)] || hit[index(nx, ny)]);
          if (!hit[index(x, y)]) enclosed[index(x, y)] = 0;
        }
      }
    }
    return enclosed;
  }

  /// Enclosed cells, kept where they form a 4-connected pocket of at least min_floor_area.
  void findFloor() {
    // The footprint's own cells count too: a floor's noise that reached past the table margin
    // stays in the segment and occupies floor cells, and under a solid footprint no view sees
    // the table anyway.
    const std::vector<char> inside = enclosedCells();
    floor_.assign(occupied_.size(), 0);
    const auto min_cells = static_cast<std::size_t>(std::ceil(params_.min_floor_area / (params_.cell * params_.cell)));
    std::vector<char> seen(occupied_.size(), 0);
    std::vector<std::size_t> pocket;
    for (std::size_t start = 0; start < inside.size(); ++start) {
      if (!inside[start] || seen[start]) continue;
      pocket.assign(1, start);
      seen[start] = 1;
      for (std::size_t head = 0; head < pocket.size(); ++head) {
        const int x = static_cast<int>(pocket[head] % width_), y = static_cast<int>(pocket[head] / width_);
        const int neighbours[4][2] = {{x + 1, y}, {x - 1, y}, {x, y + 1}, {x, y - 1}};
        for (const auto& n : neighbours) {
          if (n[0] < 0 || n[1] < 0 || n[0] >= width_ || n[1] >= height_) continue;
          const std::size_t k = index(n[0], n[1]);
          if (inside[k] && !seen[k]) {
            seen[k] = 1;
            pocket.push_back(k);
          }
        }
      }
      if (pocket.size() < min_cells) continue;
      for (std::size_t k : pocket) floor_[k] = 1;
    }
    erodeFloor();
  }

  /// The floor without its outermost cells (any of whose 8 neighbours is not floor): under a
  /// rim wider than its base (a bowl's overhang) the table is seen from the side, enclosed in
  /// the footprint all the same. Two cells cost more of the floor than they keep out.
  void erodeFloor() {
    std::vector<char> kept = floor_;
    for (int y = 0; y < height_; ++y) {
      for (int x = 0; x < width_; ++x) {
        if (!floor_[index(x, y)]) continue;
        for (int dy = -1; dy <= 1 && kept[index(x, y)]; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= width_ || ny >= height_ || !floor_[index(nx, ny)]) {
              kept[index(x, y)] = 0;
              break;
            }
          }
        }
      }
    }
    floor_.swap(kept);
  }

  FloorParams params_;
  int min_x_ = 0, max_x_ = 0, min_y_ = 0, max_y_ = 0;
  int width_ = 0, height_ = 0;
  std::vector<char> occupied_;
  std::vector<char> floor_;
};

}  // namespace

std::vector<std::vector<int>> enclosedFloors(const Scene& scene, const PreprocessedScene& prepared,
                                             const std::vector<std::vector<int>>& segments,
                                             const std::vector<int>& taken, const FloorParams& params) {
  std::vector<std::vector<int>> added(segments.size());
  if (!prepared.has_table || !scene.cloud || segments.empty() || !(params.cell > 0.0f)) return added;
  const Cloud& input = *scene.cloud;
  Eigen::Vector3f up = prepared.table_plane.head<3>();
  const float up_norm = up.norm();
  if (!(up_norm > 0.0f)) return added;
  up /= up_norm;
  const Eigen::Vector3f helper = std::fabs(up.x()) < 0.9f ? Eigen::Vector3f::UnitX() : Eigen::Vector3f::UnitY();
  const Eigen::Vector3f e1 = up.cross(helper).normalized();
  const Eigen::Vector3f e2 = up.cross(e1);

  const auto height = [&](const Eigen::Vector3f& p) { return prepared.tableHeight(p); };
  std::vector<Footprint> footprints;
  footprints.reserve(segments.size());
  for (const std::vector<int>& segment : segments) {
    std::vector<Eigen::Vector3f> usable;
    std::vector<float> heights;
    for (int i : segment) {
      if (i >= 0 && static_cast<std::size_t>(i) < input.size() && isUsablePoint(input[i])) {
        usable.push_back(input[i].getVector3fMap());
        heights.push_back(height(usable.back()));
      }
    }
    if (raisedBase(heights, prepared.table_margin, kMinRaisedCells * params.cell)) usable.clear();  // no floor
    footprints.emplace_back(withoutSparseCells(usable), e1, e2, params);
  }
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (prepared.input_to_voxel[i] >= 0) continue;
    const PointT& p = input[i];
    if (!isUsablePoint(p) || !scene.inRegionOfInterest(p.getVector3fMap())) continue;
    const float h = height(p.getVector3fMap());
    if (h < -prepared.table_margin || h > prepared.table_margin) continue;
    if (std::binary_search(taken.begin(), taken.end(), static_cast<int>(i))) continue;
    const auto cell = cellOf(p.getVector3fMap(), e1, e2, params.cell);
    for (std::size_t s = 0; s < footprints.size(); ++s) {
      if (!footprints[s].onFloor(cell)) continue;
      added[s].push_back(static_cast<int>(i));  // input order: sorted
      break;
    }
  }
  return added;
}

}  // namespace symmetry_segmentation
