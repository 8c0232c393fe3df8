#pragma once
// Reading and writing scenes in the on-disk layout:
//   scene/cloud.ply | cloud.pcd    x y z; optional normals, rgb, PLY camera element
//   scene/occupancy.bt | .ot       optional OctoMap in the cloud's frame
//   scene/table_plane.txt          optional "a b c d"
//   scene/labels.txt               optional ground truth, one integer per point
//   scene/scene_info.yaml          optional: kind, seed, sensor origins (written by make_scene)
// Every failure throws InputError with a one-line "<file>: <problem>" message.

#include <memory>
#include <string>
#include <vector>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/scene.h"

namespace symmetry_segmentation {

struct SceneLoadOptions {
  bool load_occupancy = true;
  bool load_labels = true;
};

/// Loads a scene directory or a single cloud file (.ply / .pcd).
Scene loadScene(const std::string& path, const SceneLoadOptions& options = {});

/// Reads a PLY or PCD cloud. Sets has_normals / has_color / sensor_origins of `scene`.
void loadCloudFile(const std::string& path, Scene& scene);

std::shared_ptr<octomap::OcTree> loadOctomapFile(const std::string& path);
PlaneCoefficients loadPlaneFile(const std::string& path);
std::vector<int> loadLabelsFile(const std::string& path, std::size_t expected_count);

/// Writes `scene` in the layout above (binary PLY with normals and colour, occupancy.bt,
/// table_plane.txt, labels.txt, scene_info.yaml), creating the directory.
void saveScene(const Scene& scene, const std::string& directory);

}  // namespace symmetry_segmentation
