#pragma once
// Parameters of every method, loaded from YAML (config/default.yaml documents each one).

#include <string>

#include "symmetry_segmentation/preprocessing.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace YAML {
class Node;
}

namespace symmetry_segmentation {

struct EuclideanParams {
  float cluster_tolerance = 0.02f;  ///< Max gap between points of one cluster (m).
  int min_cluster_size = 30;        ///< In downsampled points.
  int max_cluster_size = 1000000;
};

struct LccpParams {
  float voxel_resolution = 0.005f;    ///< Supervoxel voxel size (m), the paper's baseline value.
  float seed_resolution = 0.04f;      ///< Supervoxel seed spacing (m).
  float color_importance = 0.0f;
  float spatial_importance = 1.0f;
  float normal_importance = 4.0f;
  float concavity_tolerance = 10.0f;  ///< Degrees.
  float smoothness_threshold = 0.1f;
  int min_segment_size = 3;           ///< Supervoxels; smaller segments are merged.
  bool use_extended_convexity = false;
  bool use_sanity_criterion = true;
  int min_points = 30;                ///< Segments with fewer input points are dropped.
};

struct SegmentationConfig {
  PreprocessParams preprocessing;
  EuclideanParams euclidean;
  LccpParams lccp;
  SymmetryParams symmetry;
};

/// Defaults overridden by whatever `node` sets (nested maps, e.g. symmetry: {filter: {s_occl: 0.97}});
/// unknown keys throw InputError.
SegmentationConfig configFromYaml(const YAML::Node& node);
/// Throws InputError (naming the file) on unreadable files, bad YAML or unknown keys.
SegmentationConfig loadConfigFile(const std::string& path);
/// Sets one dotted key to a value given as text, e.g. ("lccp.concavity_tolerance", "15") or
/// ("symmetry.filter.s_occl", "0.97").
void setConfigValue(SegmentationConfig& config, const std::string& key, const std::string& value);

}  // namespace symmetry_segmentation
