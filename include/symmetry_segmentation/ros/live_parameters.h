#pragma once
// Live algorithm parameters over dynamic_reconfigure, one server per section of the parameter
// schema, in that section's namespace: ~symmetry/filter serves s_occl and s_smooth, so a live
// parameter has one name, ~symmetry/filter/s_occl, whether it was set at start-up (rosparam) or
// while the node runs. The generated Config types come from cfg/Live<Section>.cfg, which read
// cfg/live_parameters.yaml; nothing here names a parameter.

#include <functional>
#include <iomanip>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <boost/thread/recursive_mutex.hpp>
#include <dynamic_reconfigure/Config.h>
#include <dynamic_reconfigure/server.h>
#include <ros/node_handle.h>

#include "symmetry_segmentation/segmentation_config.h"

namespace symmetry_segmentation {

/// Applies requested live values (dotted keys, YAML text) as a whole and returns the values in
/// force afterwards for the same keys: the requested ones when they were accepted, the previous
/// ones when the configuration they make was rejected.
using LiveChange = std::function<ConfigValues(const ConfigValues& requested)>;

/// A section's server, whatever its generated type.
class LiveSection {
 public:
  virtual ~LiveSection() = default;
  /// Dotted section, e.g. "symmetry.filter".
  virtual const std::string& section() const = 0;
  /// Dotted keys of the parameters it serves.
  virtual std::vector<std::string> keys() const = 0;
};

/// Dotted keys of the parameters of a generated Config type in `section`.
template <class ConfigT>
std::vector<std::string> liveKeys(const std::string& section) {
  std::vector<std::string> keys;
  for (const auto& description : ConfigT::__getParamDescriptions__()) keys.push_back(section + "." + description->name);
  return keys;
}

/// A number as text that reads back as the same double.
inline std::string exactText(double value) {
  std::ostringstream text;
  text << std::setprecision(17) << value;
  return text.str();
}

/// The values of `config` as dotted keys with YAML text.
template <class ConfigT>
ConfigValues liveValues(const std::string& section, const ConfigT& config) {
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  ConfigValues values;
  for (const auto& p : message.bools) values.emplace_back(section + "." + p.name, p.value ? "true" : "false");
  for (const auto& p : message.ints) values.emplace_back(section + "." + p.name, std::to_string(p.value));
  for (const auto& p : message.doubles) values.emplace_back(section + "." + p.name, exactText(p.value));
  return values;
}

/// Appends to `message` the parameters `names_and_types` (name, dynamic_reconfigure type "bool",
/// "int" or "double") of `section`, read from `values` (dotted keys with YAML text; others are
/// ignored). Throws InputError when one is missing or does not read as its type.
void setLiveValues(const std::string& section, const ConfigValues& values, dynamic_reconfigure::Config& message,
                   const std::vector<std::pair<std::string, std::string>>& names_and_types);

/// Sets the parameters of `config` from `values`, as above.
template <class ConfigT>
void setLiveValues(const std::string& section, const ConfigValues& values, ConfigT& config) {
  std::vector<std::pair<std::string, std::string>> names_and_types;
  for (const auto& description : ConfigT::__getParamDescriptions__()) {
    names_and_types.emplace_back(description->name, description->type);
  }
  dynamic_reconfigure::Config message;
  setLiveValues(section, values, message, names_and_types);
  config.__fromMessage__(message);
}

/// A dynamic_reconfigure server for one section in namespace `node_handle` (~symmetry/filter).
template <class ConfigT>
class LiveSectionServer : public LiveSection {
 public:
  /// Starts from `in_force` (the configuration loaded at start-up), not from the .cfg defaults,
  /// and reports changes to `change`. `mutex` is shared by every server of the node, so live
  /// changes of different sections never interleave.
  LiveSectionServer(std::string section, const ros::NodeHandle& node_handle, boost::recursive_mutex& mutex,
                    const SegmentationConfig& in_force, LiveChange change)
      : section_(std::move(section)), change_(std::move(change)), server_(mutex, node_handle) {
    ConfigT config;
    ConfigValues values;
    for (const auto& key : keys()) values.emplace_back(key, configValueText(in_force, key));
    setLiveValues(section_, values, config);
    server_.updateConfig(config);
    server_.setCallback([this](ConfigT& requested, uint32_t) { reconfigure(requested); });
  }

  const std::string& section() const override { return section_; }
  std::vector<std::string> keys() const override { return liveKeys<ConfigT>(section_); }

 private:
  // dynamic_reconfigure publishes and stores (on the parameter server) whatever `requested`
  // holds on return: the values in force.
  void reconfigure(ConfigT& requested) { setLiveValues(section_, change_(liveValues(section_, requested)), requested); }

  std::string section_;
  LiveChange change_;
  dynamic_reconfigure::Server<ConfigT> server_;
};

}  // namespace symmetry_segmentation
