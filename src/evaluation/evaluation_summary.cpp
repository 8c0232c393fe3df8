#include "symmetry_segmentation/evaluation/evaluation_summary.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace symmetry_segmentation {

const char* const kOverallKind = "overall";
const char* const kUnknownKind = "unknown";

namespace {

// Sigmas given on the command line or from the standard list may differ by rounding only.
bool sameSigma(double a, double b) { return std::abs(a - b) < 1e-9; }

std::string reportedKind(const std::string& kind) { return kind.empty() ? kUnknownKind : kind; }

SummaryRow poolScenes(const Configuration& configuration, const std::string& kind, double sigma,
                      const std::vector<const SceneEvaluation*>& scenes) {
  SummaryRow row;
  row.configuration = configuration;
  row.kind = kind;
  row.sigma = sigma;
  row.scenes = scenes.size();
  double time_sum = 0.0;
  std::size_t timed = 0;
  for (const SceneEvaluation* scene : scenes) {
    row.counts += countMatches(scene->overlap, sigma);
    if (scene->time_ms >= 0.0) {
      time_sum += scene->time_ms;
      ++timed;
    }
  }
  row.metrics = computeMetrics(row.counts);
  if (timed > 0) row.mean_time_ms = time_sum / static_cast<double>(timed);
  return row;
}

}  // namespace

std::string Configuration::label() const {
  if (parameter_key.empty()) return method;
  return method + " (" + parameter_key + "=" + parameter_value + ")";
}

bool Configuration::operator==(const Configuration& other) const {
  return method == other.method && parameter_key == other.parameter_key &&
         parameter_value == other.parameter_value;
}

const std::vector<double>& standardSigmas() {
  static const std::vector<double> sigmas = {0.5, 0.75, 0.9};
  return sigmas;
}

std::vector<Configuration> configurationsOf(const std::vector<SceneEvaluation>& evaluations) {
  std::vector<Configuration> configurations;
  for (const SceneEvaluation& evaluation : evaluations) {
    if (std::find(configurations.begin(), configurations.end(), evaluation.configuration) ==
        configurations.end()) {
      configurations.push_back(evaluation.configuration);
    }
  }
  return configurations;
}

std::vector<SummaryRow> summarize(const std::vector<SceneEvaluation>& evaluations,
                                  const std::vector<double>& sigmas) {
  std::vector<double> sorted_sigmas = sigmas;
  std::sort(sorted_sigmas.begin(), sorted_sigmas.end());
  sorted_sigmas.erase(std::unique(sorted_sigmas.begin(), sorted_sigmas.end(), sameSigma),
                      sorted_sigmas.end());

  std::vector<SummaryRow> rows;
  for (const Configuration& configuration : configurationsOf(evaluations)) {
    std::map<std::string, std::vector<const SceneEvaluation*>> by_kind;
    std::vector<const SceneEvaluation*> all;
    for (const SceneEvaluation& evaluation : evaluations) {
      if (!(evaluation.configuration == configuration)) continue;
      by_kind[reportedKind(evaluation.kind)].push_back(&evaluation);
      all.push_back(&evaluation);
    }
    for (const auto& [kind, scenes] : by_kind) {
      for (double sigma : sorted_sigmas) rows.push_back(poolScenes(configuration, kind, sigma, scenes));
    }
    for (double sigma : sorted_sigmas) rows.push_back(poolScenes(configuration, kOverallKind, sigma, all));
  }
  return rows;
}

const SummaryRow* bestOverallRow(const std::vector<SummaryRow>& rows, const std::string& method,
                                 double sigma) {
  const SummaryRow* best = nullptr;
  for (const SummaryRow& row : rows) {
    if (row.configuration.method != method || row.kind != kOverallKind || !sameSigma(row.sigma, sigma))
      continue;
    if (!best || row.metrics.f > best->metrics.f) best = &row;
  }
  return best;
}

const SummaryRow* overallRow(const std::vector<SummaryRow>& rows, const Configuration& configuration,
                             double sigma) {
  for (const SummaryRow& row : rows) {
    if (row.configuration == configuration && row.kind == kOverallKind && sameSigma(row.sigma, sigma))
      return &row;
  }
  return nullptr;
}

}  // namespace symmetry_segmentation
