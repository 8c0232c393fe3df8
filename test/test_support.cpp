#include "test_support.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <boost/filesystem.hpp>

namespace test_support {

std::string toolPath(const std::string& tool) { return std::string(TOOLS_DIR) + "/" + tool; }

CommandResult runCommand(const std::string& command) {
  CommandResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) throw std::runtime_error("popen failed for: " + command);
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

std::string makeTempDir(const std::string& name) {
  const boost::filesystem::path dir = boost::filesystem::path(TEST_TMP_DIR) / name;
  boost::filesystem::remove_all(dir);
  boost::filesystem::create_directories(dir);
  return dir.string();
}

void writeTextFile(const std::string& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary);
  out << content;
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::string readTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool haveSharedData() { return boost::filesystem::is_directory(SHARED_DATA_DIR); }
std::string sharedDataDir() { return SHARED_DATA_DIR; }
std::string sourceDir() { return SOURCE_DIR; }

}  // namespace test_support
