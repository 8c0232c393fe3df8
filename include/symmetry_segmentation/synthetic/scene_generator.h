#pragma once
// Deterministic synthetic tabletop scenes with ground truth: a seeded layout of a scene kind,
// seen by a virtual depth camera from several poses on an arc, fused into one labelled cloud
// with normals plus an OctoMap. Same options => bit-identical scene.

#include <cstdint>
#include <string>
#include <vector>

#include "symmetry_segmentation/scene.h"
#include "symmetry_segmentation/synthetic/scene_kind.h"
#include "symmetry_segmentation/synthetic/scene_layout.h"
#include "symmetry_segmentation/synthetic/view_fusion.h"
#include "symmetry_segmentation/synthetic/virtual_camera.h"

namespace symmetry_segmentation {
namespace synthetic {

struct GeneratorOptions {
  SceneKind kind = SceneKind::Clutter;
  uint32_t seed = 0;
  int num_views = 4;             ///< Camera poses on the arc (1-16).
  double arc_degrees = 60.0;     ///< Spread of the poses around the table, centred in front.
  double min_distance = 0.8;     ///< Camera distance to the look-at point (m), drawn per view.
  double max_distance = 0.95;
  double min_elevation_deg = 38.0;  ///< How far the cameras look down, drawn per view.
  double max_elevation_deg = 48.0;
  double voxel_size = 0.003;          ///< Fusion voxel (m).
  double octomap_resolution = 0.01;   ///< OctoMap leaf size (m).
  double octomap_max_range = 3.0;
  bool build_occupancy = true;
  CameraIntrinsics intrinsics;
  DepthNoiseModel noise;
  RealismOptions realism;  ///< Room, prints, books, more shapes, shading (default: none).
  /// One organized frame as a single RGB-D camera gives it (see useDepthSensor): in the
  /// camera's optical frame, no normals, no OctoMap, no table plane, NaN where there is no
  /// depth; labels per pixel. The camera stands in front of the table at a random distance,
  /// elevation and azimuth (+-25 deg).
  bool single_view = false;
};

struct GeneratedScene {
  Scene scene;
  SceneLayout layout;
  std::vector<CameraPose> cameras;
  /// The layout's world frame to the scene cloud's (a single view is in its camera's frame).
  Eigen::Isometry3d world_to_scene = Eigen::Isometry3d::Identity();
};

/// Throws InputError naming the first bad option.
void validate(const GeneratorOptions& options);

/// Sets up a single organized view from a depth sensor model: "kinect" (structured light,
/// 1/8 px disparity steps, projector shadows) or "realsense" (D435-like active stereo
/// registered to the colour camera: wider noise, 1/16 px steps). Throws InputError otherwise.
void useDepthSensor(GeneratorOptions& options, const std::string& sensor);
/// "kinect", "realsense".
const std::vector<std::string>& depthSensorNames();

/// Camera poses on the arc in front of (-y side of) `focus`, drawn from `random`.
std::vector<CameraPose> cameraArc(const GeneratorOptions& options, const Eigen::Vector3d& focus, Random& random);

/// The scene with its layout and cameras (for tests and tools that need the ground truth).
GeneratedScene generate(const GeneratorOptions& options);

/// The scene only: cloud with normals and colour, labels, OctoMap, table plane z = 0, sensor
/// origins, kind and name "<kind>_seed<seed>".
Scene generateScene(const GeneratorOptions& options);

}  // namespace synthetic
}  // namespace symmetry_segmentation
