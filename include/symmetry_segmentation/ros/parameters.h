#pragma once
// The node's algorithm parameters come from the private namespace under the same nested names
// as config/default.yaml (e.g. ~symmetry/filter/s_occl), so `rosparam load` of that file works.

#include <string>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

#include "symmetry_segmentation/segmentation_config.h"

namespace symmetry_segmentation {

/// Sections of SegmentationConfig that map to parameter namespaces.
const std::vector<std::string>& configSections();

/// Applies every leaf under `section_value` (a struct) as "section.key.subkey" = value to
/// `config`. Keys the core does not know, or values of the wrong type, are reported in
/// `errors` (one line each) and skipped; the rest is applied.
void applyParameters(const std::string& section, XmlRpc::XmlRpcValue& section_value, SegmentationConfig& config,
                     std::vector<std::string>& errors);

/// A parameter value as the text setConfigValue expects (bool "true"/"false", numbers exact).
/// Throws InputError for arrays, structs and other types.
std::string parameterText(XmlRpc::XmlRpcValue& value);

}  // namespace symmetry_segmentation
