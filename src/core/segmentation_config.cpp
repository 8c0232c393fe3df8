// YAML and text values -> SegmentationConfig, through the parameter schema. Unknown keys are
// errors (a typo must not silently use a default), and a configuration is validated once, after
// every value is in: a rule tying two parameters must not depend on the order they were given in.
#include "symmetry_segmentation/segmentation_config.h"

#include <cmath>

#include <yaml-cpp/yaml.h>

#include "config_schema.h"
#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {
namespace {

// Scalars are quoted; lists and maps are only named, since YAML::Dump of a cyclic alias
// (a: &x [*x]) would recurse forever.
std::string describeValue(const YAML::Node& value) {
  if (value.IsScalar()) return "'" + value.Scalar() + "'";
  if (value.IsSequence()) return "(a list)";
  if (value.IsMap()) return "(a map)";
  return "(empty)";
}

/// `value` as the field's type; InputError when it is not one.
ParameterValue typedValue(const ParameterInfo& info, const YAML::Node& value) {
  const std::string invalid = "parameter '" + info.key + "' has an invalid value " + describeValue(value);
  try {
    if (info.type == "string_list") {
      if (!value.IsSequence()) throw InputError(invalid + ": expected a list of names");
      std::vector<std::string> names;
      for (const auto& item : value) {
        if (!item.IsScalar()) throw InputError(invalid + ": expected a list of names");
        names.push_back(item.Scalar());
      }
      return names;
    }
    if (!value.IsScalar()) throw InputError(invalid);
    if (info.type == "bool") return value.as<bool>();
    if (info.type == "int") return value.as<int>();
    return value.as<float>();
  } catch (const YAML::Exception&) {
    throw InputError(invalid);
  }
}

/// Sets one value, or records why it cannot be set.
void applyValue(SegmentationConfig& config, const std::string& key, const YAML::Node& value,
                std::vector<std::string>& problems) {
  const ConfigField* field = findConfigField(key);
  if (!field) {
    problems.push_back("unknown parameter '" + key + "'");
    return;
  }
  try {
    field->set(config, typedValue(field->info, value));
  } catch (const InputError& error) {
    problems.push_back(error.what());
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
void applyMap(SegmentationConfig& config, const std::string& prefix, const YAML::Node& map, int depth,
              std::vector<std::string>& problems) {
  if (depth > kMaxKeyDepth) throw InputError("configuration nested deeper than " + std::to_string(kMaxKeyDepth) + " levels at '" + prefix + "'");
  for (const auto& entry : map) {
    const std::string key = prefix + "." + keyName(entry.first, prefix);
    if (entry.second.IsMap()) {
      applyMap(config, key, entry.second, depth + 1, problems);
    } else {
      applyValue(config, key, entry.second, problems);
    }
  }
}

/// One line naming every problem.
[[noreturn]] void throwProblems(const std::vector<std::string>& problems) {
  std::string message;
  for (const std::string& problem : problems) message += (message.empty() ? "" : "; ") + problem;
  throw InputError(message);
}

SegmentationConfig validated(SegmentationConfig config, std::vector<std::string> problems) {
  for (std::string& problem : configProblems(config)) problems.push_back(std::move(problem));
  if (!problems.empty()) throwProblems(problems);
  return config;
}

}  // namespace

std::vector<std::string> configProblems(const SegmentationConfig& config) {
  std::vector<std::string> problems;
  for (const ConfigField& field : configFields()) {
    const ParameterInfo& info = field.info;
    if (info.type != "float" && info.type != "int") continue;
    const ParameterValue value = field.get(config);
    const double number = info.type == "int" ? std::get<int>(value) : std::get<float>(value);
    if (!(number >= info.min && number <= info.max)) {  // also rejects NaN
      problems.push_back(info.key + " must be in " + rangeText(info) + ", got " + formatParameterValue(value));
    }
  }
  for (const ConfigSection& section : configSections()) {
    for (const auto& rule : section.rules) {
      std::string problem = rule(config);
      if (!problem.empty()) problems.push_back(std::move(problem));
    }
  }
  return problems;
}

SegmentationConfig configFromYaml(const YAML::Node& node) {
  SegmentationConfig config;
  if (!node || node.IsNull()) return config;
  if (!node.IsMap()) throw InputError("configuration must be a map of sections");
  std::vector<std::string> problems;
  for (const auto& section : node) {
    const std::string section_name = keyName(section.first, "");
    if (!section.second.IsMap()) throw InputError("configuration section '" + section_name + "' must be a map");
    applyMap(config, section_name, section.second, 2, problems);
  }
  return validated(std::move(config), std::move(problems));
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

SegmentationConfig configWithValues(const SegmentationConfig& base, const ConfigValues& values) {
  SegmentationConfig config = base;
  std::vector<std::string> problems;
  for (const auto& [key, text] : values) {
    YAML::Node node;
    try {
      node = YAML::Load(text);
    } catch (const YAML::Exception&) {
      problems.push_back("parameter '" + key + "' has an unparsable value '" + text + "'");
      continue;
    }
    applyValue(config, key, node, problems);
  }
  return validated(std::move(config), std::move(problems));
}

void setConfigValue(SegmentationConfig& config, const std::string& key, const std::string& value) {
  config = configWithValues(config, {{key, value}});
}

std::string configValueText(const SegmentationConfig& config, const std::string& key) {
  const ConfigField* field = findConfigField(key);
  if (!field) throw InputError("unknown parameter '" + key + "'");
  return formatParameterValue(field->get(config));
}

}  // namespace symmetry_segmentation
