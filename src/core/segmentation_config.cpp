// YAML <-> parameter structs. Unknown keys are errors: a typo must not silently use a default.
#include "symmetry_segmentation/segmentation_config.h"

#include <functional>
#include <map>

#include <yaml-cpp/yaml.h>

#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {
namespace {

using Setter = std::function<void(SegmentationConfig&, const YAML::Node&)>;

template <typename T, typename Section>
Setter field(Section SegmentationConfig::*section, T Section::*member) {
  return [section, member](SegmentationConfig& config, const YAML::Node& value) {
    config.*section.*member = value.as<T>();
  };
}

template <typename T, typename Part>
Setter symmetryField(Part SymmetryParams::*part, T Part::*member) {
  return [part, member](SegmentationConfig& config, const YAML::Node& value) {
    config.symmetry.*part.*member = value.as<T>();
  };
}

const std::map<std::string, Setter>& setters() {
  using C = SegmentationConfig;
  static const std::map<std::string, Setter> table = {
      {"preprocessing.voxel_size", field(&C::preprocessing, &PreprocessParams::voxel_size)},
      {"preprocessing.remove_table", field(&C::preprocessing, &PreprocessParams::remove_table)},
      {"preprocessing.table_margin", field(&C::preprocessing, &PreprocessParams::table_margin)},
      {"preprocessing.ransac_distance", field(&C::preprocessing, &PreprocessParams::ransac_distance)},
      {"preprocessing.ransac_iterations", field(&C::preprocessing, &PreprocessParams::ransac_iterations)},
      {"preprocessing.normal_radius", field(&C::preprocessing, &PreprocessParams::normal_radius)},
      {"preprocessing.max_range", field(&C::preprocessing, &PreprocessParams::max_range)},
      {"euclidean.cluster_tolerance", field(&C::euclidean, &EuclideanParams::cluster_tolerance)},
      {"euclidean.min_cluster_size", field(&C::euclidean, &EuclideanParams::min_cluster_size)},
      {"euclidean.max_cluster_size", field(&C::euclidean, &EuclideanParams::max_cluster_size)},
      {"lccp.voxel_resolution", field(&C::lccp, &LccpParams::voxel_resolution)},
      {"lccp.seed_resolution", field(&C::lccp, &LccpParams::seed_resolution)},
      {"lccp.color_importance", field(&C::lccp, &LccpParams::color_importance)},
      {"lccp.spatial_importance", field(&C::lccp, &LccpParams::spatial_importance)},
      {"lccp.normal_importance", field(&C::lccp, &LccpParams::normal_importance)},
      {"lccp.concavity_tolerance", field(&C::lccp, &LccpParams::concavity_tolerance)},
      {"lccp.smoothness_threshold", field(&C::lccp, &LccpParams::smoothness_threshold)},
      {"lccp.min_segment_size", field(&C::lccp, &LccpParams::min_segment_size)},
      {"lccp.use_extended_convexity", field(&C::lccp, &LccpParams::use_extended_convexity)},
      {"lccp.use_sanity_criterion", field(&C::lccp, &LccpParams::use_sanity_criterion)},
      {"lccp.min_points", field(&C::lccp, &LccpParams::min_points)},
      {"symmetry.threads", field(&C::symmetry, &SymmetryParams::threads)},
#define SYMSEG_DETECTION(name) {"symmetry.detection." #name, symmetryField(&SymmetryParams::detection, &SymmetryDetectionParams::name)}
      SYMSEG_DETECTION(supervoxel_voxel), SYMSEG_DETECTION(supervoxel_seed), SYMSEG_DETECTION(merge_normal_angle_deg),
      SYMSEG_DETECTION(boundary_radius), SYMSEG_DETECTION(curve_link_radius), SYMSEG_DETECTION(min_curve_points),
      SYMSEG_DETECTION(tangent_half_window), SYMSEG_DETECTION(max_tangent_angle_deg),
      SYMSEG_DETECTION(min_match_distance), SYMSEG_DETECTION(max_match_distance),
      SYMSEG_DETECTION(mean_shift_angle_deg), SYMSEG_DETECTION(mean_shift_distance),
      SYMSEG_DETECTION(min_plane_support), SYMSEG_DETECTION(merge_plane_angle_deg),
      SYMSEG_DETECTION(merge_plane_distance), SYMSEG_DETECTION(max_hypotheses),
#undef SYMSEG_DETECTION
#define SYMSEG_CUT(name) {"symmetry.cut." #name, symmetryField(&SymmetryParams::cut, &SymmetryCutParams::name)}
      SYMSEG_CUT(dmax), SYMSEG_CUT(alpha_min_deg), SYMSEG_CUT(alpha_max_deg), SYMSEG_CUT(dbuf),
      SYMSEG_CUT(sigma_convex_deg), SYMSEG_CUT(sigma_concave_deg), SYMSEG_CUT(lambda_smooth),
      SYMSEG_CUT(lambda_sym), SYMSEG_CUT(neighbours),
#undef SYMSEG_CUT
#define SYMSEG_REFINE(name) {"symmetry.refinement." #name, symmetryField(&SymmetryParams::refinement, &SymmetryRefinementParams::name)}
      SYMSEG_REFINE(enabled), SYMSEG_REFINE(icp_iterations), SYMSEG_REFINE(icp_max_correspondence),
#undef SYMSEG_REFINE
#define SYMSEG_FILTER(name) {"symmetry.filter." #name, symmetryField(&SymmetryParams::filter, &SymmetryFilterParams::name)}
      SYMSEG_FILTER(s_occl), SYMSEG_FILTER(s_smooth), SYMSEG_FILTER(smooth_normal_angle_deg),
      SYMSEG_FILTER(min_segment_points), SYMSEG_FILTER(duplicate_overlap),
#undef SYMSEG_FILTER
  };
  return table;
}

void applyValue(SegmentationConfig& config, const std::string& key, const YAML::Node& value) {
  const auto it = setters().find(key);
  if (it == setters().end()) throw InputError("unknown parameter '" + key + "'");
  try {
    it->second(config, value);
  } catch (const YAML::Exception&) {
    throw InputError("parameter '" + key + "' has an invalid value '" + YAML::Dump(value) + "'");
  }
}

// Nested maps become dotted keys: symmetry: {filter: {s_occl: x}} sets "symmetry.filter.s_occl".
void applyMap(SegmentationConfig& config, const std::string& prefix, const YAML::Node& map) {
  for (const auto& entry : map) {
    const std::string key = prefix + "." + entry.first.as<std::string>();
    if (entry.second.IsMap()) {
      applyMap(config, key, entry.second);
    } else {
      applyValue(config, key, entry.second);
    }
  }
}

void validate(const SegmentationConfig& config) {
  if (!(config.preprocessing.voxel_size > 0.0f)) throw InputError("preprocessing.voxel_size must be > 0");
  if (!(config.preprocessing.normal_radius > 0.0f)) throw InputError("preprocessing.normal_radius must be > 0");
  if (!(config.euclidean.cluster_tolerance > 0.0f)) throw InputError("euclidean.cluster_tolerance must be > 0");
  if (!(config.lccp.voxel_resolution > 0.0f) || !(config.lccp.seed_resolution > config.lccp.voxel_resolution)) {
    throw InputError("lccp needs 0 < voxel_resolution < seed_resolution");
  }
  const auto& sym = config.symmetry;
  if (!(sym.detection.supervoxel_voxel > 0.0f) || !(sym.detection.supervoxel_seed > sym.detection.supervoxel_voxel)) {
    throw InputError("symmetry.detection needs 0 < supervoxel_voxel < supervoxel_seed");
  }
  if (!(sym.detection.mean_shift_angle_deg > 0.0f) || !(sym.detection.mean_shift_distance > 0.0f)) {
    throw InputError("symmetry.detection mean-shift bandwidths must be > 0");
  }
  if (!(sym.cut.dmax > 0.0f) || !(sym.cut.dbuf > sym.cut.dmax)) throw InputError("symmetry.cut needs 0 < dmax < dbuf");
  if (!(sym.cut.alpha_min_deg < sym.cut.alpha_max_deg)) throw InputError("symmetry.cut needs alpha_min_deg < alpha_max_deg");
  if (!(sym.cut.sigma_convex_deg > 0.0f) || !(sym.cut.sigma_concave_deg > 0.0f)) {
    throw InputError("symmetry.cut sigmas must be > 0");
  }
  if (sym.cut.neighbours < 1 || sym.cut.neighbours > 50) throw InputError("symmetry.cut.neighbours must be in [1, 50]");
  if (sym.threads < 0) throw InputError("symmetry.threads must be >= 0");
}

}  // namespace

SegmentationConfig configFromYaml(const YAML::Node& node) {
  SegmentationConfig config;
  if (!node || node.IsNull()) return config;
  if (!node.IsMap()) throw InputError("configuration must be a map of sections");
  for (const auto& section : node) {
    const std::string section_name = section.first.as<std::string>();
    if (!section.second.IsMap()) throw InputError("configuration section '" + section_name + "' must be a map");
    applyMap(config, section_name, section.second);
  }
  validate(config);
  return config;
}

SegmentationConfig loadConfigFile(const std::string& path) {
  YAML::Node node;
  try {
    node = YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw InputError(path, "cannot open configuration file");
  } catch (const YAML::Exception& e) {
    throw InputError(path, std::string("invalid YAML: ") + e.what());
  }
  try {
    return configFromYaml(node);
  } catch (const InputError& e) {
    throw InputError(path, e.what());
  }
}

void setConfigValue(SegmentationConfig& config, const std::string& key, const std::string& value) {
  YAML::Node node;
  try {
    node = YAML::Load(value);
  } catch (const YAML::Exception&) {
    throw InputError("parameter '" + key + "' has an unparsable value '" + value + "'");
  }
  applyValue(config, key, node);
  validate(config);
}

}  // namespace symmetry_segmentation
