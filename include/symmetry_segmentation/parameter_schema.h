#pragma once
// One schema for every parameter. Each parameter is declared once, next to the struct that holds
// it (a `describeParameters` overload): its key, range, unit and one-line doc; its default is the
// struct member's initializer. Setting values (YAML files, --set, ROS parameters), validation,
// the documented config/default.yaml and the node's live subset all derive from it.

#include <functional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace symmetry_segmentation {

struct ParameterInfo {
  std::string key;            ///< Dotted, e.g. "symmetry.filter.s_occl" (ROS: ~symmetry/filter/s_occl).
  std::string type;           ///< "bool", "int", "float" or "string_list".
  std::string default_value;  ///< YAML text.
  double min = 0.0;           ///< Inclusive range of a number.
  double max = 0.0;
  std::string unit;           ///< "m", "deg", "points", ... or empty.
  std::string doc;            ///< One line.
  bool live = false;          ///< May change while the node runs (dynamic_reconfigure).
};

using ParameterValue = std::variant<bool, int, float, std::vector<std::string>>;

/// The parameters of one struct, in the order they are documented, and the rules that tie
/// several of them together.
template <typename Params>
class ParameterList {
 public:
  struct Field {
    ParameterInfo info;  ///< `key` is the name within the struct's section; no default yet.
    std::function<void(Params&, const ParameterValue&)> set;  ///< The value has the field's type.
    std::function<ParameterValue(const Params&)> get;
  };
  /// An empty string when `params` satisfy it, else the problem.
  using Rule = std::function<std::string(const Params&)>;

  ParameterList& add(const char* name, float Params::*member, double min, double max, const char* unit,
                     const char* doc) {
    return addField(name, member, "float", min, max, unit, doc);
  }
  ParameterList& add(const char* name, int Params::*member, int min, int max, const char* unit, const char* doc) {
    return addField(name, member, "int", min, max, unit, doc);
  }
  ParameterList& add(const char* name, bool Params::*member, const char* doc) {
    return addField(name, member, "bool", 0.0, 1.0, "", doc);
  }
  ParameterList& add(const char* name, std::vector<std::string> Params::*member, const char* doc) {
    return addField(name, member, "string_list", 0.0, 0.0, "", doc);
  }
  /// The parameter added last may change while the node runs.
  ParameterList& live() {
    fields_.back().info.live = true;
    return *this;
  }
  ParameterList& rule(Rule rule) {
    rules_.push_back(std::move(rule));
    return *this;
  }

  const std::vector<Field>& fields() const { return fields_; }
  const std::vector<Rule>& rules() const { return rules_; }

 private:
  template <typename T>
  ParameterList& addField(const char* name, T Params::*member, const char* type, double min, double max,
                          const char* unit, const char* doc) {
    Field field;
    field.info.key = name;
    field.info.type = type;
    field.info.min = min;
    field.info.max = max;
    field.info.unit = unit;
    field.info.doc = doc;
    field.set = [member](Params& params, const ParameterValue& value) { params.*member = std::get<T>(value); };
    field.get = [member](const Params& params) { return ParameterValue(params.*member); };
    fields_.push_back(std::move(field));
    return *this;
  }

  std::vector<Field> fields_;
  std::vector<Rule> rules_;
};

/// Every parameter of SegmentationConfig, section by section, with its default filled in.
const std::vector<ParameterInfo>& parameterSchema();
/// The parameter with this dotted key, or nullptr.
const ParameterInfo* findParameter(const std::string& key);

/// config/default.yaml: every parameter at its default, each with its doc, unit and range.
std::string documentedDefaultConfig();
/// cfg/live_parameters.yaml: the live parameters, read by the dynamic_reconfigure generator.
std::string liveParametersYaml();

}  // namespace symmetry_segmentation
