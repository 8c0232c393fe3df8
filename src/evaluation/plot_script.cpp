#include "symmetry_segmentation/evaluation/plot_script.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <boost/filesystem.hpp>

#include "symmetry_segmentation/errors.h"

namespace fs = boost::filesystem;

namespace symmetry_segmentation {

const char* const kPlotScriptName = "plot_precision_recall.py";

namespace {

bool isFile(const fs::path& path) {
  boost::system::error_code error;
  return fs::is_regular_file(path, error);
}

}  // namespace

std::string currentExecutablePath(const std::string& fallback) {
  boost::system::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  return error ? fallback : self.string();
}

std::string locatePlotScript(const std::string& explicit_path, const std::string& executable_path) {
  if (!explicit_path.empty()) {
    if (!isFile(explicit_path)) throw InputError(explicit_path, "plot script not found");
    return explicit_path;
  }
  if (const char* root = std::getenv("SYMSEG_ROOT")) {
    const fs::path candidate = fs::path(root) / "scripts" / kPlotScriptName;
    if (isFile(candidate)) return candidate.string();
  }
  boost::system::error_code error;
  const fs::path executable = fs::canonical(executable_path, error);
  if (!error) {
    for (fs::path dir = executable.parent_path(); !dir.empty(); dir = dir.parent_path()) {
      for (const fs::path& candidate :
           {dir / kPlotScriptName, dir / "scripts" / kPlotScriptName,
            dir / "src" / "symmetry_segmentation" / "scripts" / kPlotScriptName}) {
        if (isFile(candidate)) return candidate.string();
      }
      if (dir == dir.root_path()) break;
    }
  }
  throw InputError(kPlotScriptName,
                   "not found (pass --plot-script PATH or set SYMSEG_ROOT to the repository)");
}

void runPlotScript(const std::string& script, const std::string& csv_path,
                   const std::string& png_path, double sigma) {
  const std::string python = access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3";
  std::ostringstream sigma_text;
  sigma_text << sigma;
  // Arguments go straight to exec: no shell, so paths need no quoting.
  std::vector<std::string> arguments = {python,     script,  csv_path,         "--output",
                                        png_path,   "--sigma", sigma_text.str()};
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);

  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("cannot start " + python + " for " + script);
  if (pid == 0) {
    execvp(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) throw std::runtime_error("lost the plot process for " + script);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    throw std::runtime_error(script + ": plotting failed (exit status " + std::to_string(code) +
                             (code == 127 ? ", could not run " + python : std::string()) + ")");
  }
}

}  // namespace symmetry_segmentation
