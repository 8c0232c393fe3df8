#pragma once
// Parameters of every method, loaded from YAML (config/default.yaml documents each one).

#include <string>
#include <utility>
#include <vector>

#include "symmetry_segmentation/object_bottoms.h"
#include "symmetry_segmentation/parameter_schema.h"
#include "symmetry_segmentation/preprocessing.h"
#include "symmetry_segmentation/symmetry/symmetry_params.h"

namespace YAML {
class Node;
}

namespace symmetry_segmentation {

struct EuclideanParams {
  float cluster_tolerance = 0.02f;
  int min_cluster_size = 30;
  int max_cluster_size = 1000000;
  bool restore_object_bottoms = true;
};

inline void describeParameters(ParameterList<EuclideanParams>& list) {
  using P = EuclideanParams;
  list.add("cluster_tolerance", &P::cluster_tolerance, 0.001, 0.5, "m", "largest gap inside one object")
      .add("min_cluster_size", &P::min_cluster_size, 1, 100000000, "points", "in working-cloud points (1 cm voxels)")
      .add("max_cluster_size", &P::max_cluster_size, 1, 100000000, "points", "larger clusters are dropped")
      .add("restore_object_bottoms", &P::restore_object_bottoms,
           "give each segment back its sides' points and inside floor within the table margin (object_bottoms)")
      .rule([](const P& p) {
        return p.max_cluster_size >= p.min_cluster_size ? "" : "max_cluster_size must be >= min_cluster_size";
      });
}

struct LccpParams {
  float voxel_resolution = 0.005f;
  float seed_resolution = 0.04f;
  float color_importance = 0.0f;
  float spatial_importance = 1.0f;
  float normal_importance = 4.0f;
  float concavity_tolerance = 10.0f;
  float smoothness_threshold = 0.1f;
  int min_segment_size = 3;
  bool use_extended_convexity = false;
  bool use_sanity_criterion = true;
  int min_points = 30;
  bool restore_object_bottoms = true;
};

inline void describeParameters(ParameterList<LccpParams>& list) {
  using P = LccpParams;
  list.add("voxel_resolution", &P::voxel_resolution, 0.001, 1.0, "m", "supervoxel voxel size (the paper's baseline value)")
      .add("seed_resolution", &P::seed_resolution, 0.001, 2.0, "m", "supervoxel seed spacing")
      .add("color_importance", &P::color_importance, 0.0, 100.0, "", "supervoxel colour weight")
      .add("spatial_importance", &P::spatial_importance, 0.0, 100.0, "", "supervoxel spatial weight")
      .add("normal_importance", &P::normal_importance, 0.0, 100.0, "", "supervoxel normal weight")
      .add("concavity_tolerance", &P::concavity_tolerance, 0.0, 180.0, "deg", "larger merges more across concave edges")
      .add("smoothness_threshold", &P::smoothness_threshold, 0.0, 10.0, "", "LCCP smoothness threshold")
      .add("min_segment_size", &P::min_segment_size, 0, 100000, "supervoxels",
           "smaller segments are merged into a neighbour")
      .add("use_extended_convexity", &P::use_extended_convexity, "LCCP extended convexity")
      .add("use_sanity_criterion", &P::use_sanity_criterion, "LCCP sanity criterion")
      .add("min_points", &P::min_points, 0, 100000000, "points", "segments with fewer input points are dropped")
      .add("restore_object_bottoms", &P::restore_object_bottoms,
           "give each segment back its sides' points and inside floor within the table margin (object_bottoms)")
      .rule([](const P& p) {
        return p.seed_resolution > p.voxel_resolution ? "" : "needs voxel_resolution < seed_resolution";
      });
}

struct SegmentationConfig {
  PreprocessParams preprocessing;
  ObjectBottomParams object_bottoms;
  EuclideanParams euclidean;
  LccpParams lccp;
  SymmetryParams symmetry;
};

/// Dotted keys with values as YAML text, e.g. {"symmetry.filter.s_occl", "0.97"}.
using ConfigValues = std::vector<std::pair<std::string, std::string>>;

/// Defaults overridden by whatever `node` sets (nested maps, e.g. symmetry: {filter: {s_occl: 0.97}}),
/// validated once. Unknown keys, bad values and violated rules throw InputError naming each.
SegmentationConfig configFromYaml(const YAML::Node& node);
/// Throws InputError (naming the file) on unreadable files, bad YAML or a bad configuration.
SegmentationConfig loadConfigFile(const std::string& path);
/// `base` with every value applied, then validated once as a whole, so the order of the values
/// does not matter. Throws InputError naming every problem; `base` is never modified.
SegmentationConfig configWithValues(const SegmentationConfig& base, const ConfigValues& values);
/// One dotted key set to a value given as YAML text, e.g. ("lccp.concavity_tolerance", "15").
/// Throws InputError and leaves `config` as it was when the result would be invalid.
void setConfigValue(SegmentationConfig& config, const std::string& key, const std::string& value);
/// The value of one dotted key as YAML text. Throws InputError for an unknown key.
std::string configValueText(const SegmentationConfig& config, const std::string& key);
/// Every problem of `config` (out-of-range values, violated rules), one line each; empty if valid.
std::vector<std::string> configProblems(const SegmentationConfig& config);

}  // namespace symmetry_segmentation
