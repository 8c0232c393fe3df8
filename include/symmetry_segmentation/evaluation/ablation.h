#pragma once
// --ablate: the symmetry method once with its full stage list and once without each stage that
// can be left out (the list still runs without it), on each data set given; per data set, the
// paper's P, R and F at one IoU threshold and the change against the full list (or, on a data
// set without ground truth, the segment count), with each stage's median time in the full run.
// This is how a stage earns its place: what the method loses without it, on data it was not
// made for.

#include <ostream>
#include <string>
#include <vector>

#include "symmetry_segmentation/evaluation/segmentation_metric.h"
#include "symmetry_segmentation/segmentation_config.h"

namespace symmetry_segmentation {

/// One list to run: the full one (`removed` empty) or the full one without one stage.
struct AblationVariant {
  std::string removed;
  std::vector<std::string> stages;
};

/// The full list, then the list without each stage (every occurrence of it) that leaves a list
/// that can run, in the order the stages first appear.
std::vector<AblationVariant> ablationVariants(const std::vector<std::string>& stages);

/// Accumulated results of one variant on one data set.
struct AblationTotals {
  MatchCounts counts;          ///< At the report's sigma; labelled scenes only.
  std::size_t segments = 0;    ///< Over every scene.
};

struct DataSetAblation {
  std::string name;
  std::size_t scenes = 0;
  bool labelled = true;  ///< Every scene has ground truth.
  std::vector<AblationVariant> variants;
  std::vector<AblationTotals> totals;  ///< Per variant.
  /// Per stage of the full list (first appearance order): its time per scene, summed over its
  /// runs in the list, in the full run.
  std::vector<std::pair<std::string, std::vector<double>>> stage_ms;
  std::vector<double> total_ms;  ///< Per scene, the full run's total.
};

/// Adds one scene's full-run timings to `ablation.stage_ms` and `total_ms`.
void addStageTimes(DataSetAblation& ablation, const std::vector<std::string>& stages, const Timings& timings);

/// A Markdown table: the full list, then one row per stage of the list (removable or not), with
/// P, R, F (and their change) or segment counts without it, and its median time (the full
/// list's row: the median total).
void printAblationTable(const DataSetAblation& ablation, double sigma, std::ostream& out);

}  // namespace symmetry_segmentation
