#include "symmetry_segmentation/evaluation/parameter_sweep.h"

#include <cctype>

#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {

namespace {

std::string trimmed(const std::string& text) {
  std::size_t begin = 0, end = text.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
  return text.substr(begin, end - begin);
}

}  // namespace

ParameterSweep parseSweep(const std::string& text) {
  const std::string usage = "expected section.key=v1,v2,... but got '" + text + "'";
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos) throw InputError("--sweep", usage);

  ParameterSweep sweep;
  sweep.key = trimmed(text.substr(0, equals));
  const std::size_t dot = sweep.key.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == sweep.key.size())
    throw InputError("--sweep", usage);
  sweep.section = sweep.key.substr(0, dot);

  const std::string list = text.substr(equals + 1);
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = list.find(',', start);
    const std::string value =
        trimmed(list.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (value.empty()) throw InputError("--sweep", "empty value in '" + text + "'");
    sweep.values.push_back(value);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return sweep;
}

bool sweepAppliesTo(const ParameterSweep& sweep, const std::string& method) {
  return sweep.section == method || sweep.section == "preprocessing";
}

}  // namespace symmetry_segmentation
