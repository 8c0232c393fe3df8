#include "symmetry_segmentation/voxel_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/point_validity.h"

namespace symmetry_segmentation {

VoxelGridResult voxelDownsample(const Cloud& cloud, const std::vector<int>& indices, float leaf_size,
                                bool average_normals) {
  if (!(leaf_size > 0.0f)) throw InputError("voxel size must be positive");
  using Key = std::array<std::int64_t, 3>;
  std::vector<std::pair<Key, int>> keyed;
  keyed.reserve(indices.size());
  const double inverse = 1.0 / leaf_size;
  for (int index : indices) {
    const auto& p = cloud.points[index];
    // A coordinate beyond ~9e18 leaves would make the int64 key conversion undefined.
    if (!isUsablePoint(p)) continue;
    keyed.push_back({Key{static_cast<std::int64_t>(std::floor(p.x * inverse)),
                         static_cast<std::int64_t>(std::floor(p.y * inverse)),
                         static_cast<std::int64_t>(std::floor(p.z * inverse))},
                     index});
  }
  std::sort(keyed.begin(), keyed.end());

  VoxelGridResult result;
  result.cloud = std::make_shared<Cloud>();
  for (std::size_t begin = 0; begin < keyed.size();) {
    std::size_t end = begin;
    while (end < keyed.size() && keyed[end].first == keyed[begin].first) ++end;
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero(),
                    rgb = Eigen::Vector3d::Zero();
    std::vector<int> members;
    members.reserve(end - begin);
    for (std::size_t i = begin; i < end; ++i) {
      const auto& p = cloud.points[keyed[i].second];
      xyz += Eigen::Vector3d(p.x, p.y, p.z);
      if (average_normals && std::isfinite(p.normal_x) && std::isfinite(p.normal_y) &&
          std::isfinite(p.normal_z)) {
        normal += Eigen::Vector3d(p.normal_x, p.normal_y, p.normal_z);
      }
      rgb += Eigen::Vector3d(p.r, p.g, p.b);
      members.push_back(keyed[i].second);
    }
    const double n = static_cast<double>(end - begin);
    PointT centroid;
    centroid.x = static_cast<float>(xyz.x() / n);
    centroid.y = static_cast<float>(xyz.y() / n);
    centroid.z = static_cast<float>(xyz.z() / n);
    centroid.r = static_cast<std::uint8_t>(std::lround(rgb.x() / n));
    centroid.g = static_cast<std::uint8_t>(std::lround(rgb.y() / n));
    centroid.b = static_cast<std::uint8_t>(std::lround(rgb.z() / n));
    const double normal_length = normal.norm();
    if (average_normals && normal_length > 1e-9) {
      centroid.normal_x = static_cast<float>(normal.x() / normal_length);
      centroid.normal_y = static_cast<float>(normal.y() / normal_length);
      centroid.normal_z = static_cast<float>(normal.z() / normal_length);
    } else {
      centroid.normal_x = centroid.normal_y = centroid.normal_z = std::numeric_limits<float>::quiet_NaN();
    }
    centroid.curvature = 0.0f;
    result.cloud->push_back(centroid);
    std::sort(members.begin(), members.end());
    result.members.push_back(std::move(members));
    begin = end;
  }
  return result;
}

}  // namespace symmetry_segmentation
