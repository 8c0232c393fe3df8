#include "symmetry_segmentation/synthetic/table_placement.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace symmetry_segmentation {
namespace synthetic {
namespace {

constexpr int kAttemptsPerRegion = 300;
constexpr int kRegionGrowths = 12;
constexpr double kGrowthStep = 0.03;

}  // namespace

TablePlacer::TablePlacer(const TableRegion& region, const TableRegion& limit, Random& random)
    : region_(region), limit_(limit), random_(random) {}

bool TablePlacer::fits(const std::vector<Footprint>& footprints, double gap) const {
  for (const auto& footprint : footprints) {
    Eigen::Vector2d min, max;
    footprintBounds(footprint, min, max);
    if ((min.array() < region_.min.array()).any() || (max.array() > region_.max.array()).any()) return false;
    for (const auto& other : placed_) {
      if (separation(footprint, other) < gap) return false;
    }
  }
  return true;
}

void TablePlacer::place(std::vector<SyntheticObject>& group, double gap, double max_yaw) {
  for (int growth = 0; growth <= kRegionGrowths; ++growth) {
    for (int attempt = 0; attempt < kAttemptsPerRegion; ++attempt) {
      const double x = random_.uniform(region_.min.x(), region_.max.x());
      const double y = random_.uniform(region_.min.y(), region_.max.y());
      const double yaw = random_.uniform(-max_yaw, max_yaw);
      const Eigen::Isometry3d placement = uprightPose(x, y, 0.0, yaw);
      std::vector<Footprint> footprints;
      for (const auto& member : group) {
        SyntheticObject moved = member;
        moved.pose = placement * member.pose;
        footprints.push_back(moved.worldFootprint());
      }
      if (!fits(footprints, gap)) continue;
      for (auto& member : group) member.pose = placement * member.pose;
      placed_.insert(placed_.end(), footprints.begin(), footprints.end());
      return;
    }
    region_.min = (region_.min.array() - kGrowthStep).max(limit_.min.array());
    region_.max = (region_.max.array() + kGrowthStep).min(limit_.max.array());
  }
  throw std::runtime_error("synthetic scene layout: could not place an object on the table");
}

void TablePlacer::place(SyntheticObject& object, double gap, double max_yaw) {
  std::vector<SyntheticObject> group{object};
  place(group, gap, max_yaw);
  object = group.front();
}

void TablePlacer::reserve(const SyntheticObject& object) { placed_.push_back(object.worldFootprint()); }

}  // namespace synthetic
}  // namespace symmetry_segmentation
