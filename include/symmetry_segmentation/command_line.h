#pragma once
// The argument loop the command-line tools share: walk the arguments, take an option's value,
// and stop with "<tool>: <problem>" and exit code 2 on a bad command line.

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>

namespace symmetry_segmentation {

class CommandLine {
 public:
  CommandLine(std::string tool, int argc, char** argv) : tool_(std::move(tool)), argc_(argc), argv_(argv) {}

  /// Moves to the next argument; false when none is left.
  bool next() { return ++index_ < argc_; }
  std::string current() const { return argv_[index_]; }
  /// The argument after the current option, which must exist.
  std::string value() {
    if (index_ + 1 >= argc_) usageError("option " + current() + " needs a value");
    return argv_[++index_];
  }

  /// The option's value as a whole-string integer in [min, max].
  int intValue(int min, int max) {
    const std::string option = current();
    const std::string text = value();
    char* end = nullptr;
    errno = 0;
    const long number = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || errno != 0 || *end != '\0' || number < min || number > max) {
      usageError(option + " must be an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "], got '" +
                 text + "'");
    }
    return static_cast<int>(number);
  }

  /// The option's value as a whole-string finite number.
  double numberValue() {
    const std::string option = current();
    const std::string text = value();
    char* end = nullptr;
    errno = 0;
    const double number = std::strtod(text.c_str(), &end);
    if (text.empty() || errno != 0 || *end != '\0' || !std::isfinite(number)) {
      usageError(option + " must be a number, got '" + text + "'");
    }
    return number;
  }

  /// The option's value split as key=value (for --set section.key=value).
  std::pair<std::string, std::string> assignmentValue() {
    const std::string option = current();
    const std::string text = value();
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0) usageError(option + " expects section.key=value, got '" + text + "'");
    return {text.substr(0, eq), text.substr(eq + 1)};
  }

  [[noreturn]] void usageError(const std::string& message) const {
    std::cerr << tool_ << ": " << message << "\nrun '" << tool_ << " --help' for usage\n";
    std::exit(2);
  }

 private:
  std::string tool_;
  int argc_;
  char** argv_;
  int index_ = 0;
};

}  // namespace symmetry_segmentation
