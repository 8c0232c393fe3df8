#pragma once
// Free / occupied / unknown classification of 3D points from an OctoMap, or from an OctoMap
// ray-cast out of the cloud itself when none was recorded (single views).

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

enum class Occupancy : unsigned char { Free, Occupied, Unknown };

const char* toString(Occupancy occupancy);

struct RayCastOptions {
  double resolution = 0.01;  ///< Octree leaf size in metres.
  double max_range = -1.0;   ///< Rays longer than this are truncated (<= 0: unlimited).
};

class OccupancyMap {
 public:
  explicit OccupancyMap(std::shared_ptr<const octomap::OcTree> tree);

  /// Builds a map by inserting every finite point of `cloud` as a ray from the nearest origin.
  static OccupancyMap fromRayCasting(const Cloud& cloud, const std::vector<Eigen::Vector3f>& origins,
                                     const RayCastOptions& options = {});

  /// Unknown where the map has no node (never observed), else the node's occupancy.
  Occupancy classify(const Eigen::Vector3f& point) const;
  double resolution() const;
  const octomap::OcTree& tree() const { return *tree_; }

 private:
  std::shared_ptr<const octomap::OcTree> tree_;
};

/// The scene's own map if it has one, else one ray-cast from its sensor origins.
/// Throws InputError when neither is available.
OccupancyMap occupancyForScene(const Scene& scene, const RayCastOptions& options = {});

}  // namespace symmetry_segmentation
