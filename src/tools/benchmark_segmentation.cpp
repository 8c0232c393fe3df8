// benchmark_segmentation: per-stage wall time (median, min, max over N runs after a warm-up),
// peak memory and counts of a method on one or more scenes, excluding file loading, with the
// baselines measured in the same run for comparison.
// Exit codes: 0 success, 1 bad input or failure, 2 bad command line.
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pcl/console/print.h>

#include "symmetry_segmentation/command_line.h"
#include "symmetry_segmentation/scene_io.h"
#include "symmetry_segmentation/segmenter.h"

namespace ss = symmetry_segmentation;

namespace {

struct Options {
  std::vector<std::string> scenes;
  std::vector<std::string> methods;
  std::string config, json;
  int runs = 5;
  bool baselines = true;
};

Options parse(int argc, char** argv) {
  Options options;
  ss::CommandLine arguments("benchmark_segmentation", argc, argv);
  while (arguments.next()) {
    const std::string arg = arguments.current();
    if (arg == "-h" || arg == "--help") {
      std::cout << "usage: benchmark_segmentation <scene>... [--runs N] [--method M]... [--config F] [--json out.json]\n"
                   "                              [--no-baselines]\n"
                   "Per-stage wall time (median, min, max over N runs after one warm-up run), peak resident\n"
                   "memory and counts. Default method: "
                << ss::defaultMethod() << "; the euclidean and lccp baselines run too unless --no-baselines.\n";
      std::exit(0);
    } else if (arg == "--runs") {
      options.runs = arguments.intValue(1, 1000);
    } else if (arg == "--method") {
      options.methods.push_back(arguments.value());
    } else if (arg == "--config") {
      options.config = arguments.value();
    } else if (arg == "--json") {
      options.json = arguments.value();
    } else if (arg == "--no-baselines") {
      options.baselines = false;
    } else if (!arg.empty() && arg[0] == '-') {
      arguments.usageError("unknown option '" + arg + "'");
    } else {
      options.scenes.push_back(arg);
    }
  }
  if (options.scenes.empty()) arguments.usageError("missing <scene>");
  if (options.methods.empty()) options.methods.push_back(ss::defaultMethod());
  if (options.baselines) {
    for (const char* baseline : {"euclidean", "lccp"}) {
      if (std::find(options.methods.begin(), options.methods.end(), baseline) == options.methods.end()) {
        options.methods.emplace_back(baseline);
      }
    }
  }
  return options;
}

double peakResidentMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // kilobytes on Linux
}

struct Stats {
  double median = 0, min = 0, max = 0;
};

Stats statsOf(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  Stats stats;
  if (values.empty()) return stats;
  const std::size_t n = values.size();
  stats.median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  stats.min = values.front();
  stats.max = values.back();
  return stats;
}

}  // namespace

int main(int argc, char** argv) {
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  const Options options = parse(argc, argv);
  nlohmann::ordered_json report = nlohmann::ordered_json::array();
  try {
    const ss::SegmentationConfig config = options.config.empty() ? ss::SegmentationConfig{} : ss::loadConfigFile(options.config);
    for (const auto& scene_path : options.scenes) {
      const ss::Scene scene = ss::loadScene(scene_path);
      std::printf("scene %s: %zu input points, %d runs after 1 warm-up\n", scene.name.c_str(), scene.size(), options.runs);
      std::map<std::string, double> total_median;
      for (const auto& method : options.methods) {
        const auto segmenter = ss::makeSegmenter(method, config);
        ss::SegmentationResult last = segmenter->segment(scene);  // warm-up
        std::vector<std::string> stage_order;
        std::map<std::string, std::vector<double>> stage_times;
        for (int run = 0; run < options.runs; ++run) {
          last = segmenter->segment(scene);
          for (const auto& [stage, ms] : last.timing_ms) {
            if (!stage_times.count(stage)) stage_order.push_back(stage);
            stage_times[stage].push_back(ms);
          }
        }
        nlohmann::ordered_json entry;
        entry["scene"] = scene.name;
        entry["method"] = method;
        entry["input_points"] = scene.size();
        entry["segments"] = last.segments.size();
        std::printf("  %-10s segments %zu, peak memory so far %.0f MB\n", method.c_str(), last.segments.size(),
                    peakResidentMb());
        for (const auto& stage : stage_order) {
          const Stats stats = statsOf(stage_times[stage]);
          std::printf("    %-28s median %9.1f ms   min %9.1f   max %9.1f\n", stage.c_str(), stats.median, stats.min,
                      stats.max);
          entry["stages_ms"][stage] = {{"median", stats.median}, {"min", stats.min}, {"max", stats.max}};
          if (stage == "total") total_median[method] = stats.median;
        }
        for (const auto& [name, count] : last.counts) {
          std::printf("    %-28s %zu\n", name.c_str(), count);
          entry["counts"][name] = count;
        }
        report.push_back(entry);
      }
      const double reference = total_median[options.methods.front()];
      for (const auto& [method, ms] : total_median) {
        if (method == options.methods.front() || ms <= 0) continue;
        std::printf("  %s total is %.1fx %s\n", options.methods.front().c_str(), reference / ms, method.c_str());
      }
    }
    std::printf("peak resident memory: %.0f MB\n", peakResidentMb());
    if (!options.json.empty()) {
      std::ofstream out(options.json);
      out << nlohmann::ordered_json{{"runs", options.runs}, {"peak_memory_mb", peakResidentMb()}, {"results", report}}.dump(2)
          << "\n";
      if (!out) throw ss::InputError(options.json, "cannot write file");
    }
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "benchmark_segmentation: error: " << e.what() << "\n";
    return 1;
  }
}
