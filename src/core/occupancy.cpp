// Occupancy queries against an OctoMap; ray-cast maps for scenes recorded without one.
#include "symmetry_segmentation/occupancy.h"

#include <cmath>
#include <limits>

#include <octomap/OcTree.h>

#include "symmetry_segmentation/depth_image_occupancy.h"
#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {

const char* toString(Occupancy occupancy) {
  switch (occupancy) {
    case Occupancy::Free: return "free";
    case Occupancy::Occupied: return "occupied";
    case Occupancy::Unknown: return "unknown";
  }
  return "unknown";
}

OccupancyMap::OccupancyMap(std::shared_ptr<const octomap::OcTree> tree) : tree_(std::move(tree)) {
  if (!tree_) throw InputError("OccupancyMap needs a tree");
}

OccupancyMap::OccupancyMap(std::shared_ptr<const DepthImageOccupancy> depth_image)
    : depth_image_(std::move(depth_image)) {
  if (!depth_image_) throw InputError("OccupancyMap needs a depth image");
}

Occupancy OccupancyMap::classify(const Eigen::Vector3f& point) const {
  if (depth_image_) return depth_image_->classify(point);
  if (!point.allFinite()) return Occupancy::Unknown;
  octomap::OcTreeKey key;
  if (!tree_->coordToKeyChecked(octomap::point3d(point.x(), point.y(), point.z()), key)) {
    return Occupancy::Unknown;  // outside the representable volume: never observed
  }
  const octomap::OcTreeNode* node = tree_->search(key);
  if (!node) return Occupancy::Unknown;
  return tree_->isNodeOccupied(node) ? Occupancy::Occupied : Occupancy::Free;
}

double OccupancyMap::resolution() const {
  return depth_image_ ? depth_image_->surfaceThickness() : tree_->getResolution();
}

OccupancyMap OccupancyMap::fromRayCasting(const Cloud& cloud, const std::vector<Eigen::Vector3f>& origins,
                                          const RayCastOptions& options) {
  if (origins.empty()) throw InputError("ray-cast occupancy needs at least one sensor origin");
  if (!(options.resolution > 0.0)) throw InputError("ray-cast occupancy needs a positive resolution");
  // Each point is a ray from the origin nearest to it: in a fused cloud that is the view most
  // likely to have seen it.
  std::vector<octomap::Pointcloud> per_origin(origins.size());
  for (const auto& p : cloud.points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    const Eigen::Vector3f xyz(p.x, p.y, p.z);
    std::size_t best = 0;
    float best_distance = std::numeric_limits<float>::max();
    for (std::size_t i = 0; i < origins.size(); ++i) {
      const float d = (origins[i] - xyz).squaredNorm();
      if (d < best_distance) {
        best_distance = d;
        best = i;
      }
    }
    per_origin[best].push_back(p.x, p.y, p.z);
  }
  auto tree = std::make_shared<octomap::OcTree>(options.resolution);
  for (std::size_t i = 0; i < origins.size(); ++i) {
    if (per_origin[i].size() == 0) continue;
    const octomap::point3d origin(origins[i].x(), origins[i].y(), origins[i].z());
    // discretize: one ray per end voxel, which keeps dense single views fast.
    tree->insertPointCloud(per_origin[i], origin, options.max_range, false, true);
  }
  return OccupancyMap(tree);
}

OccupancyMap occupancyForScene(const Scene& scene, const RayCastOptions& options) {
  if (scene.occupancy) return OccupancyMap(scene.occupancy);
  if (options.from_depth_image && scene.cloud) {
    auto depth_image = DepthImageOccupancy::fromOrganizedCloud(*scene.cloud, static_cast<float>(options.resolution));
    if (depth_image) return OccupancyMap(std::move(depth_image));
  }
  if (scene.sensor_origins.empty()) {
    throw InputError(scene.cloud_path, "no OctoMap and no sensor origin to ray-cast one from");
  }
  return OccupancyMap::fromRayCasting(*scene.cloud, scene.sensor_origins, options);
}

}  // namespace symmetry_segmentation
