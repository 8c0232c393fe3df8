// YAML <-> parameter structs. Unknown keys are errors: a typo must not silently use a default.
#include "symmetry_segmentation/segmentation_config.h"

#include <cmath>
#include <functional>
#include <map>
#include <sstream>

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
      {"preprocessing.adaptive_table_margin", field(&C::preprocessing, &PreprocessParams::adaptive_table_margin)},
      {"preprocessing.restore_object_bottoms", field(&C::preprocessing, &PreprocessParams::restore_object_bottoms)},
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
      SYMSEG_DETECTION(upright_hypotheses),
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
      SYMSEG_FILTER(min_segment_points), SYMSEG_FILTER(duplicate_overlap), SYMSEG_FILTER(seam_crease_angle_deg),
      SYMSEG_FILTER(island_gap), SYMSEG_FILTER(twin_free_fraction), SYMSEG_FILTER(color_seam_difference),
#undef SYMSEG_FILTER
  };
  return table;
}

// Scalars are quoted; lists and maps are only named, since YAML::Dump of a cyclic alias
// (a: &x [*x]) would recurse forever.
std::string describeValue(const YAML::Node& value) {
  if (value.IsScalar()) return "'" + value.Scalar() + "'";
  if (value.IsSequence()) return "(a list)";
  if (value.IsMap()) return "(a map)";
  return "(empty)";
}

void applyValue(SegmentationConfig& config, const std::string& key, const YAML::Node& value) {
  const auto it = setters().find(key);
  if (it == setters().end()) throw InputError("unknown parameter '" + key + "'");
  try {
    it->second(config, value);
  } catch (const YAML::Exception&) {
    throw InputError("parameter '" + key + "' has an invalid value " + describeValue(value));
  }
}

// Keys must be plain names: yaml-cpp would throw a bare conversion error for `? [a] : 1`.
std::string keyName(const YAML::Node& key, const std::string& prefix) {
  if (!key.IsScalar()) {
    throw InputError("configuration keys must be plain names" + (prefix.empty() ? "" : " (in '" + prefix + "')"));
  }
  return key.Scalar();
}

// Deepest dotted key is "symmetry.filter.s_occl"; anything deeper is a typo or a cyclic alias
// (symmetry: &a {filter: *a}), which would otherwise recurse until the stack overflows.
constexpr int kMaxKeyDepth = 4;

// Nested maps become dotted keys: symmetry: {filter: {s_occl: x}} sets "symmetry.filter.s_occl".
void applyMap(SegmentationConfig& config, const std::string& prefix, const YAML::Node& map, int depth) {
  if (depth > kMaxKeyDepth) throw InputError("configuration nested deeper than " + std::to_string(kMaxKeyDepth) + " levels at '" + prefix + "'");
  for (const auto& entry : map) {
    const std::string key = prefix + "." + keyName(entry.first, prefix);
    if (entry.second.IsMap()) {
      applyMap(config, key, entry.second, depth + 1);
    } else {
      applyValue(config, key, entry.second);
    }
  }
}

// ---- Validation: every parameter in a range the methods can run with --------------------------

void requireRange(const std::string& key, double value, double low, double high) {
  if (!(value >= low && value <= high)) {  // also rejects NaN
    std::ostringstream message;
    message << key << " must be in [" << low << ", " << high << "], got " << value;
    throw InputError(message.str());
  }
}

void requirePositive(const std::string& key, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) throw InputError(key + " must be a finite number > 0");
}

void requireNonNegative(const std::string& key, double value) {
  if (!(value >= 0.0) || !std::isfinite(value)) throw InputError(key + " must be a finite number >= 0");
}

void requireAngle(const std::string& key, double degrees) {
  if (!(degrees > 0.0 && degrees <= 180.0)) throw InputError(key + " must be an angle in (0, 180] degrees");
}

void requireAtLeast(const std::string& key, long long value, long long minimum) {
  if (value < minimum) throw InputError(key + " must be >= " + std::to_string(minimum));
}

void validatePreprocessing(const PreprocessParams& p) {
  requireRange("preprocessing.voxel_size", p.voxel_size, 1e-3, 1.0);
  requireNonNegative("preprocessing.table_margin", p.table_margin);
  requirePositive("preprocessing.ransac_distance", p.ransac_distance);
  requireRange("preprocessing.ransac_iterations", p.ransac_iterations, 1, 1000000);
  requirePositive("preprocessing.normal_radius", p.normal_radius);
  requireNonNegative("preprocessing.max_range", p.max_range);
}

void validateEuclidean(const EuclideanParams& e) {
  requirePositive("euclidean.cluster_tolerance", e.cluster_tolerance);
  requireAtLeast("euclidean.min_cluster_size", e.min_cluster_size, 1);
  requireAtLeast("euclidean.max_cluster_size", e.max_cluster_size, e.min_cluster_size);
}

void validateLccp(const LccpParams& l) {
  requireRange("lccp.voxel_resolution", l.voxel_resolution, 1e-3, 1.0);
  requirePositive("lccp.seed_resolution", l.seed_resolution);
  if (!(l.seed_resolution > l.voxel_resolution)) throw InputError("lccp needs 0 < voxel_resolution < seed_resolution");
  requireNonNegative("lccp.color_importance", l.color_importance);
  requireNonNegative("lccp.spatial_importance", l.spatial_importance);
  requireNonNegative("lccp.normal_importance", l.normal_importance);
  requireRange("lccp.concavity_tolerance", l.concavity_tolerance, 0.0, 180.0);
  requireNonNegative("lccp.smoothness_threshold", l.smoothness_threshold);
  requireAtLeast("lccp.min_segment_size", l.min_segment_size, 0);
  requireAtLeast("lccp.min_points", l.min_points, 0);
}

void validateSymmetryDetection(const SymmetryDetectionParams& d) {
  requireRange("symmetry.detection.supervoxel_voxel", d.supervoxel_voxel, 1e-3, 1.0);
  requirePositive("symmetry.detection.supervoxel_seed", d.supervoxel_seed);
  if (!(d.supervoxel_seed > d.supervoxel_voxel)) {
    throw InputError("symmetry.detection needs 0 < supervoxel_voxel < supervoxel_seed");
  }
  requireAngle("symmetry.detection.merge_normal_angle_deg", d.merge_normal_angle_deg);
  requirePositive("symmetry.detection.boundary_radius", d.boundary_radius);
  requirePositive("symmetry.detection.curve_link_radius", d.curve_link_radius);
  requireAtLeast("symmetry.detection.min_curve_points", d.min_curve_points, 1);
  requireAtLeast("symmetry.detection.tangent_half_window", d.tangent_half_window, 1);
  requireAngle("symmetry.detection.max_tangent_angle_deg", d.max_tangent_angle_deg);
  requireNonNegative("symmetry.detection.min_match_distance", d.min_match_distance);
  requirePositive("symmetry.detection.max_match_distance", d.max_match_distance);
  if (!(d.max_match_distance > d.min_match_distance)) {
    throw InputError("symmetry.detection needs min_match_distance < max_match_distance");
  }
  requireAngle("symmetry.detection.mean_shift_angle_deg", d.mean_shift_angle_deg);
  requirePositive("symmetry.detection.mean_shift_distance", d.mean_shift_distance);
  requireAtLeast("symmetry.detection.min_plane_support", d.min_plane_support, 1);
  requireAngle("symmetry.detection.merge_plane_angle_deg", d.merge_plane_angle_deg);
  requirePositive("symmetry.detection.merge_plane_distance", d.merge_plane_distance);
  requireAtLeast("symmetry.detection.max_hypotheses", d.max_hypotheses, 1);
}

void validateSymmetryCut(const SymmetryCutParams& c) {
  requirePositive("symmetry.cut.dmax", c.dmax);
  requirePositive("symmetry.cut.dbuf", c.dbuf);
  if (!(c.dbuf > c.dmax)) throw InputError("symmetry.cut needs 0 < dmax < dbuf");
  requireAngle("symmetry.cut.alpha_min_deg", c.alpha_min_deg);
  requireAngle("symmetry.cut.alpha_max_deg", c.alpha_max_deg);
  if (!(c.alpha_min_deg < c.alpha_max_deg)) throw InputError("symmetry.cut needs alpha_min_deg < alpha_max_deg");
  // Decay scales, not angles between directions: the paper's convex one is 360 degrees.
  requirePositive("symmetry.cut.sigma_convex_deg", c.sigma_convex_deg);
  requirePositive("symmetry.cut.sigma_concave_deg", c.sigma_concave_deg);
  requireNonNegative("symmetry.cut.lambda_smooth", c.lambda_smooth);
  requireNonNegative("symmetry.cut.lambda_sym", c.lambda_sym);
  requireRange("symmetry.cut.neighbours", c.neighbours, 1, 50);
}

void validateSymmetryRest(const SymmetryParams& sym) {
  requireRange("symmetry.refinement.icp_iterations", sym.refinement.icp_iterations, 0, 10000);
  requirePositive("symmetry.refinement.icp_max_correspondence", sym.refinement.icp_max_correspondence);
  requireRange("symmetry.filter.s_occl", sym.filter.s_occl, 0.0, 1.0);
  requireRange("symmetry.filter.s_smooth", sym.filter.s_smooth, 0.0, 1.0);
  requireAngle("symmetry.filter.smooth_normal_angle_deg", sym.filter.smooth_normal_angle_deg);
  requireAtLeast("symmetry.filter.min_segment_points", sym.filter.min_segment_points, 1);
  requireRange("symmetry.filter.duplicate_overlap", sym.filter.duplicate_overlap, 0.0, 1.0);
  requireRange("symmetry.filter.seam_crease_angle_deg", sym.filter.seam_crease_angle_deg, 0.0, 180.0);
  requireRange("symmetry.filter.island_gap", sym.filter.island_gap, 0.0, 0.2);
  requireRange("symmetry.filter.twin_free_fraction", sym.filter.twin_free_fraction, 0.0, 1.0);
  requireRange("symmetry.filter.color_seam_difference", sym.filter.color_seam_difference, 0.0, 200.0);
  requireRange("symmetry.threads", sym.threads, 0, 1024);
}

void validate(const SegmentationConfig& config) {
  validatePreprocessing(config.preprocessing);
  validateEuclidean(config.euclidean);
  validateLccp(config.lccp);
  validateSymmetryDetection(config.symmetry.detection);
  validateSymmetryCut(config.symmetry.cut);
  validateSymmetryRest(config.symmetry);
}

}  // namespace

SegmentationConfig configFromYaml(const YAML::Node& node) {
  SegmentationConfig config;
  if (!node || node.IsNull()) return config;
  if (!node.IsMap()) throw InputError("configuration must be a map of sections");
  for (const auto& section : node) {
    const std::string section_name = keyName(section.first, "");
    if (!section.second.IsMap()) throw InputError("configuration section '" + section_name + "' must be a map");
    applyMap(config, section_name, section.second, 2);
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
  } catch (const YAML::Exception& e) {  // whatever yaml-cpp still throws while walking the tree
    throw InputError(path, std::string("invalid configuration: ") + e.what());
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
