#include "symmetry_segmentation/evaluation/evaluation_csv.h"

#include <fstream>
#include <iomanip>
#include <sstream>

#include "symmetry_segmentation/errors.h"

namespace symmetry_segmentation {

namespace {

// RFC 4180 quoting, only where needed: names and values are free text.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string fixed(double value, int decimals) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(decimals) << value;
  return out.str();
}

std::string shortest(double value) {
  std::ostringstream out;
  out << std::setprecision(10) << value;
  return out.str();
}

}  // namespace

void writeSummaryCsv(const std::vector<SummaryRow>& rows, std::ostream& out) {
  out << "method,parameter,value,kind,sigma,scenes,segments,correct_segments,objects,"
         "found_objects,precision,recall,f,mean_best_iou,mean_time_ms\n";
  for (const SummaryRow& row : rows) {
    out << csvField(row.configuration.method) << ',' << csvField(row.configuration.parameter_key)
        << ',' << csvField(row.configuration.parameter_value) << ',' << csvField(row.kind) << ','
        << shortest(row.sigma) << ',' << row.scenes << ',' << row.counts.segments << ','
        << row.counts.correct_segments << ',' << row.counts.objects << ','
        << row.counts.found_objects << ',' << fixed(row.metrics.precision, 6) << ','
        << fixed(row.metrics.recall, 6) << ',' << fixed(row.metrics.f, 6) << ','
        << fixed(row.metrics.mean_best_iou, 6) << ','
        << (row.mean_time_ms >= 0.0 ? fixed(row.mean_time_ms, 3) : std::string()) << '\n';
  }
}

void writeSummaryCsvFile(const std::vector<SummaryRow>& rows, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError(path, "cannot open for writing");
  writeSummaryCsv(rows, out);
  out.flush();
  if (!out) throw InputError(path, "write failed");
}

}  // namespace symmetry_segmentation
