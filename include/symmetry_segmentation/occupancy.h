#pragma once
// Free / occupied / unknown classification of 3D points from an OctoMap; when none was
// recorded (single views), from the camera frame's depth image, or else from an OctoMap ray-cast
// out of the cloud itself.

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

enum class Occupancy : unsigned char { Free, Occupied, Unknown };

const char* toString(Occupancy occupancy);

class DepthImageOccupancy;

struct RayCastOptions {
  double resolution = 0.01;  ///< Octree leaf size in metres (depth image: the surface's thickness).
  double max_range = -1.0;   ///< Rays longer than this are truncated (<= 0: unlimited).
  /// A camera frame (organized cloud) without a map is classified from its depth image.
  bool from_depth_image = true;
};

class OccupancyMap {
 public:
  explicit OccupancyMap(std::shared_ptr<const octomap::OcTree> tree);
  explicit OccupancyMap(std::shared_ptr<const DepthImageOccupancy> depth_image);

  /// Builds a map by inserting every finite point of `cloud` as a ray from the nearest origin.
  static OccupancyMap fromRayCasting(const Cloud& cloud, const std::vector<Eigen::Vector3f>& origins,
                                     const RayCastOptions& options = {});

  /// Unknown where the map has no node (never observed), else the node's occupancy.
  Occupancy classify(const Eigen::Vector3f& point) const;
  double resolution() const;
  /// Null when the map is a depth image.
  const octomap::OcTree* tree() const { return tree_.get(); }
  const DepthImageOccupancy* depthImage() const { return depth_image_.get(); }

 private:
  std::shared_ptr<const octomap::OcTree> tree_;
  std::shared_ptr<const DepthImageOccupancy> depth_image_;
};

/// The scene's own map if it has one, else its camera frame's depth image (an organized cloud,
/// options.from_depth_image), else one ray-cast from its sensor origins. Throws InputError when
/// none is available.
OccupancyMap occupancyForScene(const Scene& scene, const RayCastOptions& options = {});

}  // namespace symmetry_segmentation
