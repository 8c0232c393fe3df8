#pragma once
// The argument loop the command-line tools share: walk the arguments, take an option's value,
// and stop with "<tool>: <problem>" and exit code 2 on a bad command line.

#include <cstdlib>
#include <iostream>
#include <string>

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
