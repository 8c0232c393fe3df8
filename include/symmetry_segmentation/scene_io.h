#pragma once
// Reading and writing scenes in the on-disk layout:
//   scene/cloud.ply | cloud.pcd    x y z; optional normals, rgb, PLY camera element
//   scene/occupancy.bt | .ot       optional OctoMap in the cloud's frame
//   scene/table_plane.txt          optional "a b c d"
//   scene/labels.txt               optional ground truth, one integer per point
//   scene/scene_info.yaml          optional: kind, seed, sensor origins (written by make_scene),
//                                  up: [x, y, z] (gravity's up in the cloud's frame)
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

/// How OctoMap node data is encoded.
enum class OctreeEncoding {
  Binary,     ///< .bt / binary message: 2 bits per child, free or occupied only (any tree type).
  Full,       ///< .ot / full message of an OcTree: float log-odds and a child byte per node.
  FullColor,  ///< Full message of a ColorOcTree: log-odds, 3 colour bytes, child byte per node.
};

/// Reads OctoMap node data (what follows the header of a .bt / .ot file, or the data of an
/// octomap_msgs/Octomap) into an OcTree with leaves of `resolution` (m, within [1e-4, 10]);
/// colours are dropped. The node stream is walked before OctoMap reads it: at most 16 levels,
/// no node cut off, no bytes left over (OctoMap's own readers follow garbage past the data and
/// past the tree's depth). Empty data gives an empty tree. Throws InputError("<source>: ...").
std::shared_ptr<octomap::OcTree> readOctreeData(const std::string& source, const std::string& data,
                                                OctreeEncoding encoding, double resolution);
PlaneCoefficients loadPlaneFile(const std::string& path);

/// `up` normalised; InputError("<source>: ...") when it is not finite or zero.
Eigen::Vector3f checkedUpDirection(const Eigen::Vector3f& up, const std::string& source);
std::vector<int> loadLabelsFile(const std::string& path, std::size_t expected_count);

/// Writes `scene` in the layout above (binary PLY with normals and colour - or, for an
/// organized cloud, compressed PCD keeping its layout, with normals only if it has them -
/// occupancy.bt, table_plane.txt, labels.txt, scene_info.yaml), creating the directory.
void saveScene(const Scene& scene, const std::string& directory);

}  // namespace symmetry_segmentation
