#include "symmetry_segmentation/synthetic/view_fusion.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <octomap/OcTree.h>

namespace symmetry_segmentation {
namespace synthetic {
namespace {

struct Entry {
  uint64_t voxel;
  int label;
  uint32_t view;
  uint32_t index;
};

uint64_t voxelKey(const Eigen::Vector3f& p, double voxel_size) {
  // 21 bits per axis with an offset: +-3 km at 3 mm, far beyond any scene.
  auto cell = [&](float value) {
    const int64_t i = static_cast<int64_t>(std::floor(value / voxel_size)) + (1 << 20);
    return static_cast<uint64_t>(std::clamp<int64_t>(i, 0, (1 << 21) - 1));
  };
  return (cell(p.x()) << 42) | (cell(p.y()) << 21) | cell(p.z());
}

PointT averagePoints(const std::vector<const ViewPoint*>& members, const FusionOptions& options,
                     Random& random) {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (const ViewPoint* p : members) {
    position += p->position.cast<double>();
    normal += p->normal.cast<double>();
  }
  position /= static_cast<double>(members.size());
  normal.normalize();
  for (int axis = 0; axis < 3; ++axis) normal[axis] += random.normal(0.0, options.normal_noise_sigma);
  normal.normalize();

  PointT point;
  point.x = static_cast<float>(position.x());
  point.y = static_cast<float>(position.y());
  point.z = static_cast<float>(position.z());
  point.normal_x = static_cast<float>(normal.x());
  point.normal_y = static_cast<float>(normal.y());
  point.normal_z = static_cast<float>(normal.z());
  point.curvature = 0.0f;
  const Rgb& color = members.front()->color;
  point.r = color[0];
  point.g = color[1];
  point.b = color[2];
  point.a = 255;
  return point;
}

}  // namespace

FusedCloud fuseViews(const std::vector<RenderedView>& views, const FusionOptions& options, Random& random) {
  std::vector<Entry> entries;
  std::size_t total = 0;
  for (const auto& view : views) total += view.points.size();
  entries.reserve(total);
  for (uint32_t v = 0; v < views.size(); ++v) {
    for (uint32_t i = 0; i < views[v].points.size(); ++i) {
      const ViewPoint& p = views[v].points[i];
      entries.push_back(Entry{voxelKey(p.true_position, options.voxel_size), p.label, v, i});
    }
  }
  // A total order (ties broken by view and index) keeps the result independent of sort details.
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return std::tie(a.voxel, a.label, a.view, a.index) < std::tie(b.voxel, b.label, b.view, b.index);
  });

  FusedCloud fused;
  fused.cloud.reset(new Cloud);
  std::vector<const ViewPoint*> front_side;
  std::vector<const ViewPoint*> back_side;
  for (std::size_t begin = 0; begin < entries.size();) {
    std::size_t end = begin;
    while (end < entries.size() && entries[end].voxel == entries[begin].voxel &&
           entries[end].label == entries[begin].label) {
      ++end;
    }
    front_side.clear();
    back_side.clear();
    const Eigen::Vector3f& reference = views[entries[begin].view].points[entries[begin].index].normal;
    for (std::size_t k = begin; k < end; ++k) {
      const ViewPoint& p = views[entries[k].view].points[entries[k].index];
      (p.normal.dot(reference) >= 0.0f ? front_side : back_side).push_back(&p);
    }
    for (const auto* side : {&front_side, &back_side}) {
      if (side->empty()) continue;
      fused.cloud->push_back(averagePoints(*side, options, random));
      fused.labels.push_back(entries[begin].label);
    }
    begin = end;
  }
  fused.cloud->width = static_cast<uint32_t>(fused.cloud->size());
  fused.cloud->height = 1;
  fused.cloud->is_dense = true;
  return fused;
}

std::shared_ptr<octomap::OcTree> buildOccupancy(const std::vector<RenderedView>& views, double resolution,
                                                double max_range) {
  auto tree = std::make_shared<octomap::OcTree>(resolution);
  for (const auto& view : views) {
    octomap::Pointcloud scan;
    scan.reserve(view.points.size());
    for (const auto& p : view.points) scan.push_back(p.position.x(), p.position.y(), p.position.z());
    const octomap::point3d origin(static_cast<float>(view.origin.x()), static_cast<float>(view.origin.y()),
                                  static_cast<float>(view.origin.z()));
    // discretize: one ray per end cell instead of per pixel, which keeps this fast.
    tree->insertPointCloud(scan, origin, max_range, false, true);
  }
  tree->updateInnerOccupancy();
  return tree;
}

}  // namespace synthetic
}  // namespace symmetry_segmentation
