#pragma once
// Helpers shared by the gtests: temporary directories, running the command-line tools,
// locating the optional real data in ../shared.

#include <string>

namespace test_support {

struct CommandResult {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr together.
};

/// Full path of a built tool, e.g. toolPath("segment_scene").
std::string toolPath(const std::string& tool);
/// Runs a shell command, capturing stdout and stderr.
CommandResult runCommand(const std::string& command);
/// A fresh, empty directory under the build tree for this test.
std::string makeTempDir(const std::string& name);
void writeTextFile(const std::string& path, const std::string& content);
std::string readTextFile(const std::string& path);
/// ../shared/data beside the repository, when it exists.
bool haveSharedData();
std::string sharedDataDir();
std::string sourceDir();

}  // namespace test_support
