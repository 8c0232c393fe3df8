#include "symmetry_segmentation/ros/parameters.h"

#include <yaml-cpp/yaml.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/parameter_schema.h"
#include "symmetry_segmentation/ros/live_parameters.h"
#include "symmetry_segmentation/ros/live_sections.h"

namespace symmetry_segmentation {

namespace {

void emitScalar(YAML::Emitter& out, XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      out << (static_cast<bool>(value) ? "true" : "false");
      return;
    case XmlRpc::XmlRpcValue::TypeInt:
      out << std::to_string(static_cast<int>(value));
      return;
    case XmlRpc::XmlRpcValue::TypeDouble:
      out << exactText(static_cast<double>(value));
      return;
    case XmlRpc::XmlRpcValue::TypeString:
      // Quoted when YAML would read it as something else: a string stays a string.
      out << YAML::DoubleQuoted << static_cast<std::string>(value);
      return;
    default:
      throw InputError("expected a boolean, number, string or a list of them");
  }
}

}  // namespace

std::string parameterText(XmlRpc::XmlRpcValue& value) {
  YAML::Emitter out;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeArray) {
    out << YAML::Flow << YAML::BeginSeq;
    for (int i = 0; i < value.size(); ++i) emitScalar(out, value[i]);
    out << YAML::EndSeq;
  } else {
    emitScalar(out, value);
  }
  return out.c_str();
}

void collectParameterValues(const std::string& prefix, XmlRpc::XmlRpcValue& value, ConfigValues& values,
                            std::vector<std::string>& problems) {
  if (value.getType() == XmlRpc::XmlRpcValue::TypeStruct) {
    for (auto& member : value) {
      collectParameterValues(prefix.empty() ? member.first : prefix + "." + member.first, member.second, values,
                             problems);
    }
    return;
  }
  try {
    values.emplace_back(prefix, parameterText(value));
  } catch (const InputError& error) {
    problems.push_back("~" + parameterPath(prefix) + ": " + error.what());
  }
}

AlgorithmParameters algorithmParameters(XmlRpc::XmlRpcValue& parameters, const std::set<std::string>& interface_names) {
  AlgorithmParameters result;
  ConfigValues known;
  if (parameters.getType() == XmlRpc::XmlRpcValue::TypeStruct) {
    for (auto& member : parameters) {
      if (interface_names.count(member.first)) continue;
      ConfigValues values;
      collectParameterValues(member.first, member.second, values, result.problems);
      for (auto& value : values) {
        ++result.values;
        if (findParameter(value.first)) {
          known.push_back(std::move(value));
        } else {
          result.problems.push_back("unknown parameter ~" + parameterPath(value.first) +
                                    " (neither an interface parameter of the node nor in the parameter schema)");
        }
      }
    }
  }
  try {
    const SegmentationConfig config = configWithValues(SegmentationConfig(), known);
    if (result.problems.empty()) result.config = config;
  } catch (const InputError& error) {
    result.problems.push_back(error.what());
  }
  return result;
}

}  // namespace symmetry_segmentation
