#pragma once
// Human-readable report: per method, the per-kind table of its best configuration (by overall F
// at the selection sigma), the sweep's overall P/R/F per value, and per-scene timing.

#include <ostream>
#include <vector>

#include "symmetry_segmentation/evaluation/evaluation_summary.h"

namespace symmetry_segmentation {

/// `rows` must hold the standard sigmas and `selection_sigma` (see summarize()).
void printSummaryTables(const std::vector<SummaryRow>& rows, double selection_sigma, std::ostream& out);

/// Mean / median / max of the per-scene total time of each configuration, slowest scene named.
void printTimingSummary(const std::vector<SceneEvaluation>& evaluations, std::ostream& out);

}  // namespace symmetry_segmentation
