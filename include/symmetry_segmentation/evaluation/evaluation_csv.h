#pragma once
// CSV of summary rows, one per (method, parameter value, kind, sigma); read by
// scripts/plot_precision_recall.py. Columns:
//   method,parameter,value,kind,sigma,scenes,segments,correct_segments,objects,found_objects,
//   precision,recall,f,mean_best_iou,mean_time_ms
// parameter/value are empty when nothing was swept; mean_time_ms is empty when unknown.

#include <ostream>
#include <string>
#include <vector>

#include "symmetry_segmentation/evaluation/evaluation_summary.h"

namespace symmetry_segmentation {

void writeSummaryCsv(const std::vector<SummaryRow>& rows, std::ostream& out);
/// Throws InputError naming `path` when it cannot be written.
void writeSummaryCsvFile(const std::vector<SummaryRow>& rows, const std::string& path);

}  // namespace symmetry_segmentation
