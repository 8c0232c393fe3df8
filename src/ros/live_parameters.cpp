#include "symmetry_segmentation/ros/live_parameters.h"

#include <algorithm>

#include <yaml-cpp/yaml.h>

#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {

void setLiveValues(const std::string& section, const ConfigValues& values, dynamic_reconfigure::Config& message,
                   const std::vector<std::pair<std::string, std::string>>& names_and_types) {
  for (const auto& [name, type] : names_and_types) {
    const std::string key = section + "." + name;
    const auto value = std::find_if(values.begin(), values.end(), [&key](const auto& entry) { return entry.first == key; });
    if (value == values.end()) throw InputError("no value for live parameter " + key);
    try {
      const YAML::Node node = YAML::Load(value->second);
      if (type == "bool") {
        dynamic_reconfigure::BoolParameter p;
        p.name = name;
        p.value = node.as<bool>();
        message.bools.push_back(p);
      } else if (type == "int") {
        dynamic_reconfigure::IntParameter p;
        p.name = name;
        p.value = node.as<int>();
        message.ints.push_back(p);
      } else if (type == "double") {
        dynamic_reconfigure::DoubleParameter p;
        p.name = name;
        p.value = node.as<double>();
        message.doubles.push_back(p);
      } else {
        throw InputError("live parameter " + key + " has dynamic_reconfigure type " + type);
      }
    } catch (const YAML::Exception&) {
      throw InputError("live parameter " + key + ": '" + value->second + "' is no " + type);
    }
  }
}

}  // namespace symmetry_segmentation
