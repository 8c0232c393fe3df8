#pragma once
// Scene preprocessing shared by every method: supporting plane (from the scene or RANSAC),
// removal of points on or below it, voxel-grid downsampling with a map back to the input
// points, and normals (a file's own normals are kept as given, averaged per voxel; missing
// ones are estimated and oriented toward the sensor).

#include <optional>
#include <vector>

#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

struct PreprocessParams {
  float voxel_size = 0.01f;              ///< Voxel-grid leaf size (m).
  bool remove_table = true;              ///< Find the supporting plane and drop points on/below it.
  float table_margin = 0.01f;            ///< Points closer than this above the plane are dropped (m);
                                         ///< with adaptive_table_margin, the largest margin used.
  bool adaptive_table_margin = true;     ///< Margin = 3 sigma of the table points' noise (>= 5 mm),
                                         ///< so low-noise fused clouds keep the objects' bottoms.
  bool restore_object_bottoms = true;    ///< Give segments back their sides' points within the
                                         ///< margin (object_bottoms.h); needs input normals.
  float ransac_distance = 0.01f;         ///< RANSAC inlier distance when the plane is estimated (m).
  int ransac_iterations = 500;
  float normal_radius = 0.03f;           ///< Neighbourhood radius for normal estimation (m).
  float max_range = 0.0f;                ///< Drop points farther than this from the sensor (0: keep all).
};

struct PreprocessedScene {
  Cloud::Ptr cloud;                        ///< Downsampled object points with normals.
  std::vector<int> input_to_voxel;         ///< Per input point: index into `cloud`, or -1 if dropped.
  std::vector<std::vector<int>> voxel_to_input;  ///< Per downsampled point: its input points.
  std::vector<int> kept_input_indices;     ///< Input points that survived (finite, above the table).
  bool has_table = false;
  float table_margin = 0.0f;               ///< The margin actually used (m).
  PlaneCoefficients table_plane = PlaneCoefficients::Zero();  ///< Normal points away from the table top.
  Eigen::Vector3f viewpoint = Eigen::Vector3f::Zero();         ///< Used to orient normals.
};

/// Throws InputError when nothing is left to segment (no finite point, all on the table).
PreprocessedScene preprocess(const Scene& scene, const PreprocessParams& params);

/// The margin above the table for these signed point-to-plane distances: median + 3 sigma of
/// the points within ransac_distance (robust sigma), clamped to [5 mm, params.table_margin].
float adaptiveTableMargin(const std::vector<float>& distances, const PreprocessParams& params);

/// Estimates the supporting plane of `cloud` with RANSAC; returns false if none is found. Of up to
/// three large planes (a single view may show more wall or floor than table), the one with the
/// most other points standing over it within 0.3 m, on the `viewpoint` side (without one: on
/// the side most points are on).
bool estimateSupportingPlane(const Cloud& cloud, const PreprocessParams& params,
                             const std::optional<Eigen::Vector3f>& viewpoint, PlaneCoefficients& plane);

/// Expands per-downsampled-point indices to the input points they represent (sorted).
std::vector<int> expandToInput(const PreprocessedScene& scene, const std::vector<int>& voxel_indices);

}  // namespace symmetry_segmentation
