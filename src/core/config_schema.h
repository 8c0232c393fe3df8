#pragma once
// Internal: the parameter schema bound to SegmentationConfig (parameter_schema.cpp), shared by the
// YAML loading (segmentation_config.cpp) and the documents generated from it.

#include <functional>
#include <string>
#include <vector>

#include "symmetry_segmentation/parameter_schema.h"
#include "symmetry_segmentation/segmentation_config.h"

namespace symmetry_segmentation {

struct ConfigField {
  ParameterInfo info;  ///< Full dotted key, default filled in.
  std::function<void(SegmentationConfig&, const ParameterValue&)> set;
  std::function<ParameterValue(const SegmentationConfig&)> get;
};

struct ConfigSection {
  std::string prefix;  ///< "symmetry.cut"
  std::string doc;
  std::vector<std::function<std::string(const SegmentationConfig&)>> rules;  ///< Problems name full keys.
};

const std::vector<ConfigField>& configFields();
const std::vector<ConfigSection>& configSections();
/// nullptr for an unknown key.
const ConfigField* findConfigField(const std::string& key);

/// "[min, max] unit" of a number parameter; empty for others.
std::string rangeText(const ParameterInfo& info);
/// A bound of a number parameter as text of the parameter's own type.
std::string boundText(const ParameterInfo& info, double bound);

/// A value as YAML text: the shortest decimal that reads back as the same float.
std::string formatParameterValue(const ParameterValue& value);

}  // namespace symmetry_segmentation
