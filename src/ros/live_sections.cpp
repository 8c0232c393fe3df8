#include "symmetry_segmentation/ros/live_sections.h"

#include <algorithm>
#include <set>

#include "symmetry_segmentation/LivePreprocessingConfig.h"
#include "symmetry_segmentation/LiveSymmetryCutConfig.h"
#include "symmetry_segmentation/LiveSymmetryFilterConfig.h"
#include "symmetry_segmentation/parameter_schema.h"

namespace symmetry_segmentation {

namespace {

template <class ConfigT>
LiveSectionType sectionType(const std::string& section) {
  LiveSectionType type;
  type.section = section;
  type.keys = [section] { return liveKeys<ConfigT>(section); };
  type.start = [section](const ros::NodeHandle& handle, boost::recursive_mutex& mutex, const SegmentationConfig& in_force,
                         LiveChange change) -> std::unique_ptr<LiveSection> {
    return std::make_unique<LiveSectionServer<ConfigT>>(section, handle, mutex, in_force, std::move(change));
  };
  return type;
}

}  // namespace

const std::vector<LiveSectionType>& liveSectionTypes() {
  static const std::vector<LiveSectionType> types = {
      sectionType<LivePreprocessingConfig>("preprocessing"),
      sectionType<LiveSymmetryCutConfig>("symmetry.cut"),
      sectionType<LiveSymmetryFilterConfig>("symmetry.filter"),
  };
  return types;
}

std::vector<std::string> liveSectionProblems() {
  std::set<std::string> served;
  std::vector<std::string> problems;
  for (const auto& type : liveSectionTypes()) {
    for (const auto& key : type.keys()) {
      served.insert(key);
      const ParameterInfo* info = findParameter(key);
      if (!info) {
        problems.push_back("live parameter " + key + " (cfg of section " + type.section + ") is not in the schema");
      } else if (!info->live) {
        problems.push_back("live parameter " + key + " is not live in the schema");
      }
    }
  }
  for (const auto& info : parameterSchema()) {
    if (info.live && !served.count(info.key)) {
      problems.push_back("live parameter " + info.key + " has no dynamic_reconfigure server (add cfg/Live<Section>.cfg for its section and list it in live_sections.cpp)");
    }
  }
  return problems;
}

std::string parameterPath(const std::string& dotted) {
  std::string path = dotted;
  std::replace(path.begin(), path.end(), '.', '/');
  return path;
}

}  // namespace symmetry_segmentation
