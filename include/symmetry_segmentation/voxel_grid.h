#pragma once
// Voxel-grid downsampling that remembers which input points each voxel stands for
// (pcl::VoxelGrid does not), so results can always be reported on the input cloud.

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

/// The grid cell of side `leaf` holding finite `p`.
inline std::array<std::int64_t, 3> voxelKey(const Eigen::Vector3f& p, float leaf) {
  return {static_cast<std::int64_t>(std::floor(p.x() / leaf)), static_cast<std::int64_t>(std::floor(p.y() / leaf)),
          static_cast<std::int64_t>(std::floor(p.z() / leaf))};
}

struct VoxelGridResult {
  Cloud::Ptr cloud;                         ///< One centroid per occupied voxel.
  std::vector<std::vector<int>> members;    ///< Per voxel: the input indices it averages (sorted).
};

/// Downsamples `cloud` restricted to `indices` (finite points). Voxels are ordered by their
/// grid key, so the output is deterministic. Normals are averaged and renormalised when
/// `average_normals` is set; colours are averaged.
VoxelGridResult voxelDownsample(const Cloud& cloud, const std::vector<int>& indices, float leaf_size,
                                bool average_normals);

}  // namespace symmetry_segmentation
