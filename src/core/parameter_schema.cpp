// The parameter schema of SegmentationConfig: every struct's describeParameters, bound to its
// place in the configuration, and the documents generated from it.
#include "symmetry_segmentation/parameter_schema.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <regex>
#include <sstream>

#include "config_schema.h"

namespace symmetry_segmentation {
namespace {

struct Schema {
  std::vector<ConfigField> fields;
  std::vector<ConfigSection> sections;
  std::map<std::string, std::size_t> by_key;

  /// The parameters of `Params`, found in a configuration by `access`, under `prefix`.
  template <typename Params, typename Access>
  void section(const std::string& prefix, const std::string& doc, Access access) {
    ParameterList<Params> list;
    describeParameters(list);
    const Params defaults{};
    ConfigSection bound{prefix, doc, {}};
    for (const auto& field : list.fields()) {
      ConfigField config_field;
      config_field.info = field.info;
      config_field.info.key = prefix + "." + field.info.key;
      config_field.info.default_value = formatParameterValue(field.get(defaults));
      config_field.set = [access, set = field.set](SegmentationConfig& config, const ParameterValue& value) {
        set(access(config), value);
      };
      config_field.get = [access, get = field.get](const SegmentationConfig& config) {
        return get(access(config));
      };
      by_key[config_field.info.key] = fields.size();
      fields.push_back(std::move(config_field));
    }
    for (const auto& rule : list.rules()) {
      bound.rules.push_back([access, rule, prefix, names = fieldNames(list)](const SegmentationConfig& config) {
        return withFullKeys(rule(access(config)), prefix, names);
      });
    }
    sections.push_back(std::move(bound));
  }

  template <typename Params>
  static std::vector<std::string> fieldNames(const ParameterList<Params>& list) {
    std::vector<std::string> names;
    for (const auto& field : list.fields()) names.push_back(field.info.key);
    return names;
  }

  /// A rule's problem names its parameters by their names in the section: give their full keys.
  static std::string withFullKeys(std::string problem, const std::string& prefix, const std::vector<std::string>& names) {
    if (problem.empty()) return problem;
    for (const std::string& name : names) {
      problem = std::regex_replace(problem, std::regex("(^|[^.\\w])" + name + "\\b"), "$1" + prefix + "." + name);
    }
    return problem;
  }
};

const Schema& schema() {
  static const Schema built = [] {
    Schema s;
    s.section<PreprocessParams>("preprocessing", "shared by every method: supporting plane, working cloud, normals",
                                [](auto& c) -> auto& { return c.preprocessing; });
    s.section<ObjectBottomParams>("object_bottoms",
                                  "every method (symmetry: stage object_bottoms): object sides and inside floors within the table margin",
                                  [](auto& c) -> auto& { return c.object_bottoms; });
    s.section<EuclideanParams>("euclidean", "pcl::EuclideanClusterExtraction on the working cloud",
                               [](auto& c) -> auto& { return c.euclidean; });
    s.section<LccpParams>("lccp", "pcl::SupervoxelClustering + pcl::LCCPSegmentation (the paper's baseline)",
                          [](auto& c) -> auto& { return c.lccp; });
    s.section<SymmetryParams>("symmetry", "the symmetry method (Ecins et al., ICRA 2016); (paper): the paper's value",
                              [](auto& c) -> auto& { return c.symmetry; });
    // One section per stage, in the order of the default list.
    s.section<NormalEdgeCurveParams>("symmetry.curves", "stage curves: normal-edge curves",
                                     [](auto& c) -> auto& { return c.symmetry.curves; });
    s.section<CurvePairParams>("symmetry.curve_pairs", "stage curve_pairs: planes from matched curve pairs",
                               [](auto& c) -> auto& { return c.symmetry.curve_pairs; });
    s.section<UprightHypothesisParams>("symmetry.upright", "stage upright: vertical planes from single surfaces, horizontal ones halfway up",
                                       [](auto& c) -> auto& { return c.symmetry.upright; });
    s.section<SymmetryCutParams>("symmetry.cut", "stage cut: graph cut per hypothesis; the data term of every stage",
                                 [](auto& c) -> auto& { return c.symmetry.cut; });
    s.section<SymmetryRefinementParams>("symmetry.refine", "stage refine: ICP of each segment with its reflection",
                                        [](auto& c) -> auto& { return c.symmetry.refine; });
    s.section<IslandParams>("symmetry.islands", "stage islands: groups of points apart from all others",
                            [](auto& c) -> auto& { return c.symmetry.islands; });
    s.section<FootprintParams>("symmetry.footprints", "stage footprints: planes for islands nothing covers",
                               [](auto& c) -> auto& { return c.symmetry.footprints; });
    s.section<OccluderGapParams>("symmetry.occluder_gaps", "stage occluder_gaps: planes across a hidden gap between two pieces",
                                 [](auto& c) -> auto& { return c.symmetry.occluder_gaps; });
    s.section<SymmetryFilterParams>("symmetry.filter", "stage filter: scores and thresholds, also for every later stage",
                                    [](auto& c) -> auto& { return c.symmetry.filter; });
    s.section<IslandSegmentParams>("symmetry.island_segments", "stage island_segments: islands a found plane explains",
                                   [](auto& c) -> auto& { return c.symmetry.island_segments; });
    s.section<MirrorTwinParams>("symmetry.mirror_twins", "stage mirror_twins: two like objects mirrored onto each other",
                                [](auto& c) -> auto& { return c.symmetry.mirror_twins; });
    s.section<CompositeSegmentParams>("symmetry.composites", "stage composites: two objects meeting at a concave seam",
                                      [](auto& c) -> auto& { return c.symmetry.composites; });
    s.section<NestedSegmentParams>("symmetry.nested", "stage nested: an object glued onto another's segment",
                                   [](auto& c) -> auto& { return c.symmetry.nested; });
    s.section<ColorSeamParams>("symmetry.color_seams", "stage color_seams: flush objects of different colours",
                               [](auto& c) -> auto& { return c.symmetry.color_seams; });
    s.section<CoaxialPieceParams>("symmetry.coaxial_pieces", "stage coaxial_pieces: pieces of one surface of revolution joined",
                                  [](auto& c) -> auto& { return c.symmetry.coaxial_pieces; });
    s.section<ObjectSizeParams>("symmetry.object_size", "stage object_size: only what a robot could grasp is an object",
                                [](auto& c) -> auto& { return c.symmetry.object_size; });
    s.section<DuplicateParams>("symmetry.dedup", "stage dedup: one segment per object",
                               [](auto& c) -> auto& { return c.symmetry.dedup; });
    s.section<CompletionParams>("symmetry.completion", "stage completion: each object's unseen side from its symmetry",
                                [](auto& c) -> auto& { return c.symmetry.completion; });
    s.section<StrayColorParams>("symmetry.stray_color_pieces", "stage stray_color_pieces: strips of the next object's colour",
                                [](auto& c) -> auto& { return c.symmetry.stray_color_pieces; });
    return s;
  }();
  return built;
}

/// YAML double-quoted string.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

/// A bound of a number parameter, as the parameter's own type.
std::string boundText(const ParameterInfo& info, double bound) {
  return info.type == "int" ? std::to_string(static_cast<long long>(bound)) : formatParameterValue(static_cast<float>(bound));
}

std::string rangeText(const ParameterInfo& info) {
  if (info.type != "float" && info.type != "int") return "";
  std::ostringstream text;
  text << "[" << boundText(info, info.min) << ", " << boundText(info, info.max) << "]";
  if (!info.unit.empty()) text << " " << info.unit;
  return text.str();
}

const std::vector<ConfigField>& configFields() { return schema().fields; }
const std::vector<ConfigSection>& configSections() { return schema().sections; }

const ConfigField* findConfigField(const std::string& key) {
  const auto it = schema().by_key.find(key);
  return it == schema().by_key.end() ? nullptr : &schema().fields[it->second];
}

std::string formatParameterValue(const ParameterValue& value) {
  if (const bool* flag = std::get_if<bool>(&value)) return *flag ? "true" : "false";
  if (const int* number = std::get_if<int>(&value)) return std::to_string(*number);
  if (const float* number = std::get_if<float>(&value)) {
    char text[64];
    // At least the integer digits, so 10 prints as "10", not "1e+01".
    const double magnitude = std::fabs(static_cast<double>(*number));
    const int integer_digits = magnitude >= 1.0 && std::isfinite(magnitude) ? static_cast<int>(std::log10(magnitude)) + 1 : 1;
    for (int precision = std::min(integer_digits, 9); precision <= 9; ++precision) {
      std::snprintf(text, sizeof(text), "%.*g", precision, static_cast<double>(*number));
      if (std::strtof(text, nullptr) == *number) break;
    }
    std::string result = text;
    // "2" would read back as an integer to a human; floats keep a decimal point.
    if (result.find_first_of(".en") == std::string::npos) result += ".0";
    return result;
  }
  std::string list = "[";
  for (const std::string& name : std::get<std::vector<std::string>>(value)) list += (list.size() > 1 ? ", " : "") + name;
  return list + "]";
}

const std::vector<ParameterInfo>& parameterSchema() {
  static const std::vector<ParameterInfo> infos = [] {
    std::vector<ParameterInfo> result;
    for (const ConfigField& field : configFields()) result.push_back(field.info);
    return result;
  }();
  return infos;
}

const ParameterInfo* findParameter(const std::string& key) {
  const ConfigField* field = findConfigField(key);
  return field ? &field->info : nullptr;
}

std::string documentedDefaultConfig() {
  std::ostringstream out;
  out << "# Parameters of symmetry_segmentation's methods, each at its default, with its range and unit.\n"
         "# Generated from the parameter schema (segment_scene --print-config); do not edit by hand.\n"
         "# Every key is optional; unknown keys and values out of range are errors. \"live\": may be\n"
         "# changed while the node runs (dynamic_reconfigure).\n";
  for (const ConfigSection& section : configSections()) {
    const std::size_t depth = std::count(section.prefix.begin(), section.prefix.end(), '.');
    const std::string indent(2 * depth, ' ');
    const std::string name = section.prefix.substr(section.prefix.rfind('.') + 1);
    out << indent << name << ":  # " << section.doc << "\n";
    const std::string field_indent(2 * (depth + 1), ' ');
    for (const ConfigField& field : configFields()) {
      const std::string& key = field.info.key;
      if (key.compare(0, section.prefix.size() + 1, section.prefix + ".") != 0 ||
          key.find('.', section.prefix.size() + 1) != std::string::npos) {
        continue;
      }
      std::string note = rangeText(field.info);
      if (field.info.live) note += note.empty() ? "live" : ", live";
      out << field_indent << "# " << field.info.doc << (note.empty() ? "" : "  " + note) << "\n";
      out << field_indent << key.substr(section.prefix.size() + 1) << ": " << field.info.default_value << "\n";
    }
  }
  return out.str();
}

std::string liveParametersYaml() {
  std::ostringstream out;
  out << "# The parameters the node takes while it runs (dynamic_reconfigure reads this file at build\n"
         "# time). Generated from the parameter schema (segment_scene --print-live-parameters); do not\n"
         "# edit by hand.\n";
  for (const ParameterInfo& info : parameterSchema()) {
    if (!info.live) continue;
    out << "- {key: " << info.key << ", type: " << info.type << ", default: " << info.default_value
        << ", min: " << boundText(info, info.min) << ", max: " << boundText(info, info.max) << ", unit: " << quoted(info.unit)
        << ", doc: " << quoted(info.doc) << "}\n";
  }
  return out.str();
}

}  // namespace symmetry_segmentation
