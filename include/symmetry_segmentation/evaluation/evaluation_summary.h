#pragma once
// Pools per-scene overlaps into one row per (configuration, scene kind, sigma), plus an
// "overall" kind over every scene: the numbers behind the printed table, the CSV and the plot.

#include <cstddef>
#include <string>
#include <vector>

#include "symmetry_segmentation/evaluation/segmentation_metric.h"

namespace symmetry_segmentation {

/// The kind that pools every scene of a configuration.
extern const char* const kOverallKind;
/// The kind given to scenes whose scene_info.yaml names none.
extern const char* const kUnknownKind;

/// A method with (optionally) one swept parameter set to one value.
struct Configuration {
  std::string method;
  std::string parameter_key;    ///< e.g. "lccp.concavity_tolerance"; empty when not swept.
  std::string parameter_value;  ///< As given on the command line; empty when not swept.

  std::string label() const;  ///< "method" or "method (key=value)".
  bool operator==(const Configuration& other) const;
};

/// One configuration evaluated on one scene.
struct SceneEvaluation {
  Configuration configuration;
  std::string scene;
  std::string kind;      ///< Empty is reported as kUnknownKind.
  SceneOverlap overlap;
  double time_ms = -1.0;  ///< Total segmentation time; negative when unknown.
};

struct SummaryRow {
  Configuration configuration;
  std::string kind;
  double sigma = 0.0;
  std::size_t scenes = 0;
  MatchCounts counts;
  Metrics metrics;
  double mean_time_ms = -1.0;  ///< Over scenes with a known time; negative when none.
};

/// The sigmas the paper reports.
const std::vector<double>& standardSigmas();

/// Rows ordered by configuration (first appearance), kind (alphabetical, overall last), sigma.
std::vector<SummaryRow> summarize(const std::vector<SceneEvaluation>& evaluations,
                                  const std::vector<double>& sigmas);

/// Configurations in first-appearance order.
std::vector<Configuration> configurationsOf(const std::vector<SceneEvaluation>& evaluations);

/// The overall row at `sigma` of `method` with the highest F (first on ties); null if none.
const SummaryRow* bestOverallRow(const std::vector<SummaryRow>& rows, const std::string& method,
                                 double sigma);

/// The overall row of one configuration at `sigma`; null if none.
const SummaryRow* overallRow(const std::vector<SummaryRow>& rows, const Configuration& configuration,
                             double sigma);

}  // namespace symmetry_segmentation
