#include "symmetry_segmentation/evaluation/evaluation_table.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace symmetry_segmentation {

namespace {

bool sameSigma(double a, double b) { return std::abs(a - b) < 1e-9; }

std::string number(double value, int decimals) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(decimals) << value;
  return out.str();
}

std::string milliseconds(double value) { return value >= 0.0 ? number(value, 1) : "-"; }

std::vector<std::string> methodsOf(const std::vector<SummaryRow>& rows) {
  std::vector<std::string> methods;
  for (const SummaryRow& row : rows) {
    if (std::find(methods.begin(), methods.end(), row.configuration.method) == methods.end())
      methods.push_back(row.configuration.method);
  }
  return methods;
}

void printKindTable(const std::vector<SummaryRow>& rows, const Configuration& configuration,
                    std::ostream& out) {
  const std::vector<double>& sigmas = standardSigmas();
  out << std::left << std::setw(16) << "kind" << std::right << std::setw(7) << "scenes"
      << std::setw(7) << "segs" << std::setw(7) << "objs";
  for (double sigma : sigmas) {
    const std::string s = number(sigma, 2);
    out << " |" << std::setw(7) << ("P@" + s) << std::setw(7) << ("R@" + s) << std::setw(7)
        << ("F@" + s);
  }
  out << " |" << std::setw(9) << "meanIoU" << std::setw(11) << "ms/scene" << '\n';

  // Rows come grouped by kind with sigmas ascending; print one line per kind.
  std::vector<std::string> kinds;
  for (const SummaryRow& row : rows) {
    if (row.configuration == configuration &&
        std::find(kinds.begin(), kinds.end(), row.kind) == kinds.end())
      kinds.push_back(row.kind);
  }
  for (const std::string& kind : kinds) {
    const SummaryRow* any = nullptr;
    std::ostringstream cells;
    for (double sigma : sigmas) {
      const SummaryRow* match = nullptr;
      for (const SummaryRow& row : rows) {
        if (row.configuration == configuration && row.kind == kind && sameSigma(row.sigma, sigma))
          match = &row;
      }
      cells << " |";
      if (!match) {
        cells << std::setw(21) << "-";
        continue;
      }
      any = match;
      cells << std::setw(7) << number(match->metrics.precision, 3) << std::setw(7)
            << number(match->metrics.recall, 3) << std::setw(7) << number(match->metrics.f, 3);
    }
    if (!any) continue;
    out << std::left << std::setw(16) << kind << std::right << std::setw(7) << any->scenes
        << std::setw(7) << any->counts.segments << std::setw(7) << any->counts.objects
        << cells.str() << " |" << std::setw(9) << number(any->metrics.mean_best_iou, 3)
        << std::setw(11) << milliseconds(any->mean_time_ms) << '\n';
  }
}

void printSweep(const std::vector<SummaryRow>& rows, const std::string& method, double sigma,
                const SummaryRow& best, std::ostream& out) {
  out << "sweep at sigma " << number(sigma, 2) << " (overall):\n";
  out << "  " << std::left << std::setw(34) << "parameter" << std::right << std::setw(7) << "P"
      << std::setw(7) << "R" << std::setw(7) << "F" << std::setw(11) << "ms/scene" << '\n';
  for (const SummaryRow& row : rows) {
    if (row.configuration.method != method || row.kind != kOverallKind || !sameSigma(row.sigma, sigma))
      continue;
    const std::string parameter = row.configuration.parameter_key.empty()
                                      ? std::string("(defaults)")
                                      : row.configuration.parameter_key + "=" +
                                            row.configuration.parameter_value;
    out << (row.configuration == best.configuration ? "* " : "  ") << std::left << std::setw(34)
        << parameter << std::right << std::setw(7) << number(row.metrics.precision, 3)
        << std::setw(7) << number(row.metrics.recall, 3) << std::setw(7)
        << number(row.metrics.f, 3) << std::setw(11) << milliseconds(row.mean_time_ms) << '\n';
  }
}

}  // namespace

void printSummaryTables(const std::vector<SummaryRow>& rows, double selection_sigma,
                        std::ostream& out) {
  for (const std::string& method : methodsOf(rows)) {
    const SummaryRow* best = bestOverallRow(rows, method, selection_sigma);
    if (!best) continue;
    std::size_t configurations = 0;
    for (const SummaryRow& row : rows) {
      if (row.configuration.method == method && row.kind == kOverallKind &&
          sameSigma(row.sigma, selection_sigma))
        ++configurations;
    }
    out << "== " << best->configuration.label();
    if (configurations > 1)
      out << "  [best F at sigma " << number(selection_sigma, 2) << " of " << configurations
          << " values]";
    out << '\n';
    printKindTable(rows, best->configuration, out);
    if (configurations > 1) printSweep(rows, method, selection_sigma, *best, out);
    out << '\n';
  }
}

void printTimingSummary(const std::vector<SceneEvaluation>& evaluations, std::ostream& out) {
  out << "timing (total ms per scene):\n";
  for (const Configuration& configuration : configurationsOf(evaluations)) {
    std::vector<double> times;
    const SceneEvaluation* slowest = nullptr;
    for (const SceneEvaluation& evaluation : evaluations) {
      if (!(evaluation.configuration == configuration) || evaluation.time_ms < 0.0) continue;
      times.push_back(evaluation.time_ms);
      if (!slowest || evaluation.time_ms > slowest->time_ms) slowest = &evaluation;
    }
    out << "  " << configuration.label() << ": ";
    if (times.empty()) {
      out << "no timing recorded\n";
      continue;
    }
    std::sort(times.begin(), times.end());
    double sum = 0.0;
    for (double t : times) sum += t;
    const std::size_t n = times.size();
    const double median = n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
    out << n << " scenes, mean " << number(sum / static_cast<double>(n), 1) << ", median "
        << number(median, 1) << ", max " << number(times.back(), 1) << " (" << slowest->scene
        << ")\n";
  }
}

}  // namespace symmetry_segmentation
