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

void validate(const SegmentationConfig& config) {
  if (!(config.preprocessing.voxel_size > 0.0f)) throw InputError("preprocessing.voxel_size must be > 0");
  if (!(config.preprocessing.normal_radius > 0.0f)) throw InputError("preprocessing.normal_radius must be > 0");
  if (!(config.euclidean.cluster_tolerance > 0.0f)) throw InputError("euclidean.cluster_tolerance must be > 0");
  if (!(config.lccp.voxel_resolution > 0.0f) || !(config.lccp.seed_resolution > config.lccp.voxel_resolution)) {
    throw InputError("lccp needs 0 < voxel_resolution < seed_resolution");
  }
}

}  // namespace

SegmentationConfig configFromYaml(const YAML::Node& node) {
  SegmentationConfig config;
  if (!node || node.IsNull()) return config;
  if (!node.IsMap()) throw InputError("configuration must be a map of sections");
  for (const auto& section : node) {
    const std::string section_name = section.first.as<std::string>();
    if (!section.second.IsMap()) throw InputError("configuration section '" + section_name + "' must be a map");
    for (const auto& entry : section.second) {
      applyValue(config, section_name + "." + entry.first.as<std::string>(), entry.second);
    }
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
