#pragma once
// Finding and running scripts/plot_precision_recall.py (Debian python3 + matplotlib), which turns
// the evaluation CSV into the precision-recall figure.

#include <string>

namespace symmetry_segmentation {

extern const char* const kPlotScriptName;  ///< "plot_precision_recall.py"

/// The plot script, searched in this order:
///  1. `explicit_path` when non-empty (must exist, else InputError);
///  2. $SYMSEG_ROOT/scripts/plot_precision_recall.py;
///  3. beside the executable (catkin install puts it in lib/symmetry_segmentation/);
///  4. walking up from the executable's real path, <dir>/scripts/ or
///     <dir>/src/symmetry_segmentation/scripts/ (a devel space whose workspace src/ links the
///     repository). Throws InputError when none is found.
std::string locatePlotScript(const std::string& explicit_path, const std::string& executable_path);

/// The running executable's path (/proc/self/exe), or `fallback` when unavailable.
std::string currentExecutablePath(const std::string& fallback);

/// Runs `python3 <script> <csv> --output <png> --sigma <sigma>` with /usr/bin/python3 when
/// present (the pyenv python3 lacks matplotlib), else python3 from PATH. Throws
/// std::runtime_error when the script cannot start or fails.
void runPlotScript(const std::string& script, const std::string& csv_path,
                   const std::string& png_path, double sigma);

}  // namespace symmetry_segmentation
