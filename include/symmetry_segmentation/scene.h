#pragma once
// A tabletop scene as the core library sees it: a cloud (input order preserved), optional
// occupancy, supporting plane, sensor origins and ground-truth labels.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace octomap {
class OcTree;
}

namespace symmetry_segmentation {

using PointT = pcl::PointXYZRGBNormal;
using Cloud = pcl::PointCloud<PointT>;

/// Plane a*x + b*y + c*z + d = 0 with (a, b, c) of unit length.
using PlaneCoefficients = Eigen::Vector4f;

struct Scene {
  std::string name;        ///< Directory or file base name, used in reports.
  std::string kind;        ///< Scene kind (e.g. "clutter"); empty when unknown.
  std::string cloud_path;  ///< File the cloud was read from.
  Cloud::Ptr cloud;        ///< Every point of the file, in file order (may hold NaN points).
  bool has_normals = false;
  bool has_color = false;
  /// Where the cloud was seen from (PCD VIEWPOINT, PLY camera element, scene_info.yaml).
  std::vector<Eigen::Vector3f> sensor_origins;
  std::shared_ptr<octomap::OcTree> occupancy;  ///< May be null: no map on disk.
  std::optional<PlaneCoefficients> table_plane;
  /// Gravity's up in the cloud's frame, when known (tf, an IMU, `--up`): the supporting plane
  /// is then one facing up, never a wall or a tilted box face. Unit length.
  std::optional<Eigen::Vector3f> up;
  /// Only points inside this box (cloud frame) are segmented. The table is still found in the
  /// whole cloud: a box drawn around objects need not hold the table they stand on.
  std::optional<Eigen::AlignedBox3f> region_of_interest;
  std::vector<int> labels;  ///< Ground truth per cloud point (0 = not an object); empty if none.
  /// The cloud file's own per-point "label" field as stored (e.g. the ground truth of OSD / mOSD
  /// frames, see evaluation/ground_truth.h); empty when the file has none.
  std::vector<std::uint32_t> file_labels;

  std::size_t size() const { return cloud ? cloud->size() : 0; }
  /// Whether `point` may be segmented: inside the region of interest, or there is none.
  bool inRegionOfInterest(const Eigen::Vector3f& point) const {
    return !region_of_interest || region_of_interest->contains(point);
  }
  bool hasLabels() const { return !labels.empty(); }
};

}  // namespace symmetry_segmentation
