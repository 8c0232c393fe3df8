#pragma once
// --sweep "section.key=v1,v2,...": one parameter of one method's config section, evaluated at
// each value in turn (the other parameters keep their configured values).

#include <string>
#include <vector>

namespace symmetry_segmentation {

struct ParameterSweep {
  std::string key;      ///< "section.name", as accepted by setConfigValue().
  std::string section;  ///< The part before the first '.': a method name or "preprocessing".
  std::vector<std::string> values;
};

/// Throws InputError("--sweep", ...) on a missing '=', a key without a section, or empty values.
ParameterSweep parseSweep(const std::string& text);

/// Whether a sweep applies to `method`: its section names the method, or is "preprocessing"
/// (shared by every method).
bool sweepAppliesTo(const ParameterSweep& sweep, const std::string& method);

}  // namespace symmetry_segmentation
