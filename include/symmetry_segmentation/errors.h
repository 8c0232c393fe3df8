#pragma once
#include <stdexcept>
#include <string>

namespace symmetry_segmentation {

/// Bad input: the message is one line naming the file and the problem ("<file>: <problem>").
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& problem)
      : std::runtime_error(file.empty() ? problem : file + ": " + problem) {}
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace symmetry_segmentation
