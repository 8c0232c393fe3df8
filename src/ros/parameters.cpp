#include "symmetry_segmentation/ros/parameters.h"

#include <iomanip>
#include <sstream>

#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {

const std::vector<std::string>& configSections() {
  static const std::vector<std::string> sections = {"preprocessing", "euclidean", "lccp", "symmetry"};
  return sections;
}

std::string parameterText(XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return static_cast<bool>(value) ? "true" : "false";
    case XmlRpc::XmlRpcValue::TypeInt:
      return std::to_string(static_cast<int>(value));
    case XmlRpc::XmlRpcValue::TypeDouble: {
      std::ostringstream text;
      text << std::setprecision(17) << static_cast<double>(value);
      return text.str();
    }
    case XmlRpc::XmlRpcValue::TypeString:
      return static_cast<std::string>(value);
    default:
      throw InputError("expected a boolean, number or string");
  }
}

void applyParameters(const std::string& key, XmlRpc::XmlRpcValue& value, SegmentationConfig& config,
                     std::vector<std::string>& errors) {
  if (value.getType() == XmlRpc::XmlRpcValue::TypeStruct) {
    for (auto& member : value) applyParameters(key + "." + member.first, member.second, config, errors);
    return;
  }
  try {
    setConfigValue(config, key, parameterText(value));
  } catch (const std::exception& error) {
    errors.push_back(key + ": " + error.what());
  }
}

}  // namespace symmetry_segmentation
