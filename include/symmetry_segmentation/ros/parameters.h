#pragma once
// The node's algorithm parameters come from its private namespace under the same nested names
// as config/default.yaml (e.g. ~symmetry/filter/s_occl), so `rosparam load` of that file works.
// They are read all at once at start-up and validated as one configuration.

#include <set>
#include <string>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

#include "symmetry_segmentation/segmentation_config.h"

namespace symmetry_segmentation {

/// A parameter value as YAML text (bool "true"/"false", numbers exact, strings quoted when YAML
/// would read them otherwise, lists as flow sequences). Throws InputError for structs, lists of
/// lists and other types.
std::string parameterText(XmlRpc::XmlRpcValue& value);

/// Every leaf under `value` as a dotted key (`prefix` + nested names) with YAML text. A value
/// no parameter can have is a problem naming its ROS name (~a/b/c).
void collectParameterValues(const std::string& prefix, XmlRpc::XmlRpcValue& value, ConfigValues& values,
                            std::vector<std::string>& problems);

struct AlgorithmParameters {
  SegmentationConfig config;          ///< The configuration in force: defaults when rejected.
  std::vector<std::string> problems;  ///< Empty when accepted; else every problem, one each.
  std::size_t values = 0;             ///< Values read.
};

/// The algorithm configuration the private namespace `parameters` (a struct, as getParam("~")
/// returns it) sets: every name but the `interface_names` is an algorithm parameter, applied to
/// the defaults at once and validated once. Unknown names (~symmetry/filtr/s_occl, ~sesnor_frame)
/// and bad values are problems; any problem rejects the whole configuration (defaults in force).
AlgorithmParameters algorithmParameters(XmlRpc::XmlRpcValue& parameters, const std::set<std::string>& interface_names);

}  // namespace symmetry_segmentation
