#include "symmetry_segmentation/evaluation/ablation.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "symmetry_segmentation/symmetry/stage.h"

namespace symmetry_segmentation {
namespace {

std::string fixed(double value, int decimals, bool sign = false) {
  std::ostringstream out;
  if (sign) out << std::showpos;
  out << std::fixed << std::setprecision(decimals) << value;
  return out.str();
}

double median(std::vector<double> values) {
  if (values.empty()) return -1.0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/// The stage a timing entry belongs to: "cut#2" is cut's second run.
std::string stageOfLabel(const std::string& label) { return label.substr(0, label.find('#')); }

}  // namespace

std::vector<AblationVariant> ablationVariants(const std::vector<std::string>& stages) {
  std::vector<AblationVariant> variants = {{"", stages}};
  std::vector<std::string> seen;
  for (const std::string& stage : stages) {
    if (std::find(seen.begin(), seen.end(), stage) != seen.end()) continue;
    seen.push_back(stage);
    AblationVariant variant{stage, {}};
    std::copy_if(stages.begin(), stages.end(), std::back_inserter(variant.stages),
                 [&](const std::string& other) { return other != stage; });
    if (stageListProblems(variant.stages).empty()) variants.push_back(std::move(variant));
  }
  return variants;
}

void addStageTimes(DataSetAblation& ablation, const std::vector<std::string>& stages, const Timings& timings) {
  for (const std::string& stage : stages) {
    const bool known = std::any_of(ablation.stage_ms.begin(), ablation.stage_ms.end(),
                                   [&](const auto& entry) { return entry.first == stage; });
    if (!known) ablation.stage_ms.emplace_back(stage, std::vector<double>{});
  }
  for (const auto& [label, ms] : timings) {
    if (label == "total") ablation.total_ms.push_back(ms);
  }
  for (auto& [stage, per_scene] : ablation.stage_ms) {
    double sum = 0.0;
    for (const auto& [label, ms] : timings) {
      if (stageOfLabel(label) == stage) sum += ms;
    }
    per_scene.push_back(sum);
  }
}

void printAblationTable(const DataSetAblation& ablation, double sigma, std::ostream& out) {
  const std::string at = "@" + fixed(sigma, 2);
  out << "Ablation on " << ablation.name << " (" << ablation.scenes << " scene" << (ablation.scenes == 1 ? "" : "s");
  if (ablation.labelled && !ablation.totals.empty()) out << ", " << ablation.totals.front().counts.objects << " objects";
  out << "):\n\n";
  if (ablation.labelled) {
    out << "| stage list | P" << at << " | R" << at << " | F" << at << " | change in F | segments | stage median ms |\n"
        << "|---|---|---|---|---|---|---|\n";
  } else {
    out << "| stage list | segments | change | stage median ms |\n|---|---|---|---|\n";
  }
  const AblationTotals& full = ablation.totals.front();
  const Metrics full_metrics = computeMetrics(full.counts);
  auto timeOf = [&](const std::string& stage) {
    for (const auto& [name, per_scene] : ablation.stage_ms) {
      if (name == stage) return fixed(median(per_scene), 1);
    }
    return std::string("-");
  };
  auto row = [&](const std::string& label, const AblationTotals* totals, const std::string& stage) {
    out << "| " << label << " | ";
    if (!totals) {
      out << (ablation.labelled ? "(required) | | | | | " : "(required) | | ") << timeOf(stage) << " |\n";
      return;
    }
    if (ablation.labelled) {
      const Metrics m = computeMetrics(totals->counts);
      out << fixed(m.precision, 3) << " | " << fixed(m.recall, 3) << " | " << fixed(m.f, 3) << " | "
          << (stage.empty() ? "" : fixed(m.f - full_metrics.f, 3, true)) << " | " << totals->segments << " | ";
    } else {
      out << totals->segments << " | "
          << (stage.empty() ? "" : fixed(static_cast<double>(totals->segments) - static_cast<double>(full.segments), 0, true))
          << " | ";
    }
    out << (stage.empty() ? (ablation.total_ms.empty() ? "-" : fixed(median(ablation.total_ms), 1) + " (total)")
                          : timeOf(stage))
        << " |\n";
  };
  row("full list", &full, "");
  for (const auto& [stage, per_scene] : ablation.stage_ms) {
    (void)per_scene;
    const auto variant = std::find_if(ablation.variants.begin(), ablation.variants.end(),
                                      [&](const AblationVariant& v) { return v.removed == stage; });
    const AblationTotals* totals =
        variant == ablation.variants.end() ? nullptr : &ablation.totals[variant - ablation.variants.begin()];
    row("without " + stage, totals, stage);
  }
  out << '\n';
}

}  // namespace symmetry_segmentation
