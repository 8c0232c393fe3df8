#pragma once
// The generated dynamic_reconfigure types of the live sections (cfg/Live<Section>.cfg), matched
// against the parameter schema's live parameters.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "symmetry_segmentation/ros/live_parameters.h"

namespace symmetry_segmentation {

struct LiveSectionType {
  std::string section;                           ///< Dotted, e.g. "symmetry.filter".
  std::function<std::vector<std::string>()> keys;  ///< Dotted keys its generated type holds.
  /// Starts its server in namespace `section_handle` (the private namespace + the section).
  std::function<std::unique_ptr<LiveSection>(const ros::NodeHandle& section_handle, boost::recursive_mutex& mutex,
                                             const SegmentationConfig& in_force, LiveChange change)>
      start;
};

/// One entry per cfg/Live<Section>.cfg.
const std::vector<LiveSectionType>& liveSectionTypes();

/// Where the generated types and the schema disagree, one line each: a live parameter of the
/// schema no server holds, or a served parameter the schema does not call live. Empty when they
/// agree (a new section of live parameters needs a cfg/Live<Section>.cfg and an entry here).
std::vector<std::string> liveSectionProblems();

/// "symmetry.filter" -> "symmetry/filter".
std::string parameterPath(const std::string& dotted);

}  // namespace symmetry_segmentation
