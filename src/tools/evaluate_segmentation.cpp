// evaluate_segmentation: the paper's precision / recall / F over labelled scenes, for methods run
// here (optionally over a parameter sweep) or for stored segments.json files. See --help.

#include <algorithm>
#include <chrono>
#include <exception>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <boost/filesystem.hpp>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/evaluation/ablation.h"
#include "symmetry_segmentation/evaluation/evaluation_csv.h"
#include "symmetry_segmentation/evaluation/evaluation_inputs.h"
#include "symmetry_segmentation/evaluation/evaluation_summary.h"
#include "symmetry_segmentation/evaluation/evaluation_table.h"
#include "symmetry_segmentation/evaluation/ground_truth.h"
#include "symmetry_segmentation/evaluation/parameter_sweep.h"
#include "symmetry_segmentation/evaluation/plot_script.h"
#include "symmetry_segmentation/scene_io.h"
#include "symmetry_segmentation/segmentation_config.h"
#include "symmetry_segmentation/segmenter.h"
#include "symmetry_segmentation/segments_json.h"

namespace ss = symmetry_segmentation;
namespace fs = boost::filesystem;

namespace {

constexpr int kExitInputError = 2;
constexpr int kExitRuntimeError = 1;

void printUsage(std::ostream& out) {
  out << R"(Usage: evaluate_segmentation <scene_dir>... [options]

Precision, recall and F of segmentations against ground-truth labels, as in Ecins et al.
(ICRA 2016): an object is found when a segment overlaps it with IoU > sigma; a segment is
correct when its best IoU with an object of its scene is > sigma; counts are pooled over
scenes. Reported at sigma 0.5, 0.75 and 0.9, per scene kind (scene_info.yaml; "unknown" when
absent) and overall, with the mean best IoU per object.

Each <scene_dir> is a scene directory holding labels.txt, or a directory whose subdirectories
holding labels.txt are scenes. Real frames of OSD / mOSD (Richtsfeld et al.) are read as
distributed: a .pcd file with a "label" field (0 invalid, 1-9 table, object = label / 10 for
labels >= 20), or a directory of them; their kind is the OSD category of the frame's name
(learnN / testN: boxes, stacked, occluded, cylindric, mixed, complex).

Options:
  --method M            Run method M on every scene (repeatable; default: all methods: )";
  const std::vector<std::string> methods = ss::availableMethods();
  for (std::size_t i = 0; i < methods.size(); ++i) out << (i ? ", " : "") << methods[i];
  out << R"().
  --config FILE         Method parameters (YAML) instead of the defaults.
  --segments DIR        Evaluate stored results instead of running methods:
                        DIR/<scene>/segments.json or DIR/<scene>.json (repeatable; the method
                        is named after DIR). Not combinable with --method or --sweep.
  --sweep KEY=V1,V2,..  Evaluate each value of one parameter, e.g.
                        lccp.concavity_tolerance=5,10,15,20 or
                        euclidean.cluster_tolerance=0.01,0.02,0.03 (repeatable). Applies to the
                        method its section names ("preprocessing.*": to every method).
  --csv FILE            Write one row per (method, parameter value, kind, sigma).
  --plot FILE.png       Precision-recall plot, one curve per method over its sweep, best F
                        marked (needs /usr/bin/python3 with matplotlib).
  --sigma S             IoU threshold of the plot and of each method's best sweep value
                        (default 0.9).
  --osd-parts           OSD frames at part level: each visible piece of an occluded object
                        (labels 21, 22, ...) is an object of its own (default: object level).
  --table-band M        Leave points within M metres of the table out of objects and segments
                        alike (e.g. 0.015): the plane fitted to an OSD frame's table-labelled
                        points, else the scene's table_plane.txt (default 0: off).
  --ablate              Run the symmetry method with its full stage list (symmetry.stages of
                        --config) and once without each stage the list can run without; print
                        per data set (each <scene_dir> argument is one; it may also be a scene
                        without labels, e.g. a real scan, where segment counts are reported)
                        P, R, F at --sigma and the change against the full list, and each
                        stage's median time. Not combinable with --method, --sweep, --segments,
                        --csv or --plot.
  --plot-script PATH    plot_precision_recall.py to use. Default: $SYMSEG_ROOT/scripts/, else
                        beside this executable, else found walking up from this executable's
                        real path (<dir>/scripts/ or <dir>/src/symmetry_segmentation/scripts/).
  -h, --help            This text.

Progress goes to stderr, the tables to stdout.
Exit status: 0 success; 2 bad input (arguments, scenes, config, segments files), with a
one-line message naming the file and problem; 1 other failures (e.g. plotting).
)";
}

struct Options {
  std::vector<std::string> scene_arguments;
  std::vector<std::string> methods;
  std::vector<std::string> segments_dirs;
  std::vector<std::string> sweeps;
  std::string config_path;
  std::string csv_path;
  std::string plot_path;
  std::string plot_script;
  double sigma = 0.9;
  ss::GroundTruthOptions ground_truth;
  bool help = false;
  bool ablate = false;
};

double parseSigma(const std::string& text) {
  try {
    std::size_t used = 0;
    const double sigma = std::stod(text, &used);
    if (used == text.size() && sigma >= 0.0 && sigma < 1.0) return sigma;
  } catch (const std::exception&) {
  }
  throw ss::InputError("--sigma", "expected a number in [0, 1), got '" + text + "'");
}

double parseTableBand(const std::string& text) {
  try {
    std::size_t used = 0;
    const double band = std::stod(text, &used);
    if (used == text.size() && band >= 0.0 && band <= 0.5) return band;
  } catch (const std::exception&) {
  }
  throw ss::InputError("--table-band", "expected metres in [0, 0.5], got '" + text + "'");
}

Options parseArguments(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    std::string argument = argv[i];
    if (argument == "-h" || argument == "--help") {
      options.help = true;
      continue;
    }
    if (argument == "--ablate") {
      options.ablate = true;
      continue;
    }
    if (argument == "--osd-parts") {
      options.ground_truth.osd_parts = true;
      continue;
    }
    if (argument.rfind("--", 0) != 0) {
      options.scene_arguments.push_back(argument);
      continue;
    }
    // Both "--option value" and "--option=value".
    std::string value;
    bool has_value = false;
    const std::size_t equals = argument.find('=');
    if (equals != std::string::npos) {
      value = argument.substr(equals + 1);
      argument = argument.substr(0, equals);
      has_value = true;
    }
    auto takeValue = [&]() {
      if (has_value) return value;
      if (i + 1 >= argc) throw ss::InputError(argument, "missing value");
      return std::string(argv[++i]);
    };
    if (argument == "--method") options.methods.push_back(takeValue());
    else if (argument == "--segments") options.segments_dirs.push_back(takeValue());
    else if (argument == "--sweep") options.sweeps.push_back(takeValue());
    else if (argument == "--config") options.config_path = takeValue();
    else if (argument == "--csv") options.csv_path = takeValue();
    else if (argument == "--plot") options.plot_path = takeValue();
    else if (argument == "--plot-script") options.plot_script = takeValue();
    else if (argument == "--sigma") options.sigma = parseSigma(takeValue());
    else if (argument == "--table-band") options.ground_truth.table_band = parseTableBand(takeValue());
    else throw ss::InputError(argument, "unknown option (see --help)");
  }
  return options;
}

/// One thing to evaluate on every scene: a method with its config, or a segments directory.
struct Run {
  ss::Configuration configuration;
  ss::SegmentationConfig config;
  std::unique_ptr<ss::Segmenter> segmenter;  // null in --segments mode
  std::string segments_dir;
};

std::vector<Run> planMethodRuns(const Options& options) {
  const ss::SegmentationConfig base =
      options.config_path.empty() ? ss::SegmentationConfig{} : ss::loadConfigFile(options.config_path);
  const std::vector<std::string> available = ss::availableMethods();
  std::vector<std::string> methods = options.methods.empty() ? available : options.methods;
  for (const std::string& method : methods) {
    if (std::find(available.begin(), available.end(), method) == available.end()) {
      std::string list;
      for (const std::string& name : available) list += (list.empty() ? "" : ", ") + name;
      throw ss::InputError("--method", "unknown method '" + method + "' (available: " + list + ")");
    }
  }

  std::vector<ss::ParameterSweep> sweeps;
  for (const std::string& text : options.sweeps) {
    ss::ParameterSweep sweep = ss::parseSweep(text);
    const bool used = std::any_of(methods.begin(), methods.end(), [&](const std::string& method) {
      return ss::sweepAppliesTo(sweep, method);
    });
    if (!used)
      throw ss::InputError("--sweep", "'" + sweep.key + "' applies to none of the methods run");
    sweeps.push_back(sweep);
  }

  std::vector<Run> runs;
  for (const std::string& method : methods) {
    bool swept = false;
    for (const ss::ParameterSweep& sweep : sweeps) {
      if (!ss::sweepAppliesTo(sweep, method)) continue;
      swept = true;
      for (const std::string& value : sweep.values) {
        Run run;
        run.configuration = {method, sweep.key, value};
        run.config = base;
        ss::setConfigValue(run.config, sweep.key, value);  // InputError on bad key or value
        runs.push_back(std::move(run));
      }
    }
    if (!swept) {
      Run run;
      run.configuration = {method, "", ""};
      run.config = base;
      runs.push_back(std::move(run));
    }
  }
  for (Run& run : runs) run.segmenter = ss::makeSegmenter(run.configuration.method, run.config);
  return runs;
}

std::vector<Run> planSegmentsRuns(const Options& options) {
  std::vector<Run> runs;
  for (const std::string& directory : options.segments_dirs) {
    if (!fs::is_directory(directory)) throw ss::InputError(directory, "not a directory");
    // Named after the directory, or its full path when two directories share a name.
    std::string name = fs::path(directory).lexically_normal().filename().string();
    if (name.empty() || name == ".") name = directory;
    for (const Run& run : runs) {
      if (run.configuration.method == name) name = directory;
    }
    Run run;
    run.configuration = {name, "", ""};
    run.segments_dir = directory;
    runs.push_back(std::move(run));
  }
  return runs;
}

double totalTime(const ss::Timings& timings) {
  for (auto it = timings.rbegin(); it != timings.rend(); ++it) {
    if (it->first == "total") return it->second;
  }
  return -1.0;
}

ss::SceneEvaluation evaluateRun(const Run& run, const ss::Scene& scene, const std::string& scene_dir) {
  ss::SceneEvaluation evaluation;
  evaluation.configuration = run.configuration;
  evaluation.scene = scene.name;
  evaluation.kind = scene.kind;

  ss::SegmentationResult result;
  std::string source = scene_dir;
  if (run.segmenter) {
    const auto start = std::chrono::steady_clock::now();
    try {
      result = run.segmenter->segment(scene);
    } catch (const ss::InputError& error) {
      throw ss::InputError(scene_dir, run.configuration.label() + ": " + error.what());
    }
    const double measured =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    evaluation.time_ms = totalTime(result.timing_ms);
    if (evaluation.time_ms < 0.0) evaluation.time_ms = measured;
  } else {
    source = ss::findSegmentsFile(run.segments_dir, scene.name);
    result = ss::readSegmentsJson(source);
    if (result.input_points != scene.size()) {
      throw ss::InputError(source, "input_points " + std::to_string(result.input_points) +
                                       " does not match scene " + scene_dir + " with " +
                                       std::to_string(scene.size()) + " points");
    }
    evaluation.time_ms = totalTime(result.timing_ms);
  }

  try {
    evaluation.overlap = ss::computeOverlap(scene.labels, result.segments);
  } catch (const ss::InputError& error) {
    throw ss::InputError(source, error.what());
  }
  return evaluation;
}

void writePlot(const Options& options, const std::string& script,
               const std::vector<ss::SummaryRow>& rows) {
  // The script reads the CSV; use the requested one, or a temporary file removed afterwards.
  std::string csv_path = options.csv_path;
  const bool temporary = csv_path.empty();
  if (temporary) {
    csv_path = (fs::temp_directory_path() / fs::unique_path("evaluate_segmentation-%%%%%%%%.csv")).string();
    ss::writeSummaryCsvFile(rows, csv_path);
  }
  try {
    ss::runPlotScript(script, csv_path, options.plot_path, options.sigma);
  } catch (...) {
    if (temporary) fs::remove(csv_path);
    throw;
  }
  if (temporary) fs::remove(csv_path);
}

/// --ablate: the full stage list and the list without each stage, per data set (ablation.h).
int runAblation(const Options& options) {
  if (!options.segments_dirs.empty() || !options.sweeps.empty() || !options.csv_path.empty() ||
      !options.plot_path.empty()) {
    throw ss::InputError("--ablate", "cannot be combined with --segments, --sweep, --csv or --plot");
  }
  for (const std::string& method : options.methods) {
    if (method != "symmetry") throw ss::InputError("--ablate", "ablates the stages of the symmetry method only");
  }
  const ss::SegmentationConfig base =
      options.config_path.empty() ? ss::SegmentationConfig{} : ss::loadConfigFile(options.config_path);
  const std::vector<ss::AblationVariant> variants = ss::ablationVariants(base.symmetry.stages);
  std::vector<std::unique_ptr<ss::Segmenter>> segmenters;
  for (const ss::AblationVariant& variant : variants) {
    ss::SegmentationConfig config = base;
    config.symmetry.stages = variant.stages;
    segmenters.push_back(ss::makeSegmenter("symmetry", config));
  }
  std::vector<std::vector<std::string>> data_sets;
  for (const std::string& argument : options.scene_arguments) data_sets.push_back(ss::findDataSetScenes(argument));

  for (std::size_t d = 0; d < data_sets.size(); ++d) {
    ss::DataSetAblation ablation;
    ablation.name = fs::path(options.scene_arguments[d]).lexically_normal().filename().string();
    if (ablation.name.empty() || ablation.name == ".") ablation.name = options.scene_arguments[d];
    ablation.variants = variants;
    ablation.totals.resize(variants.size());
    for (const std::string& scene_dir : data_sets[d]) {
      const ss::Scene scene = ss::loadLabelledScene(scene_dir, options.ground_truth);
      ++ablation.scenes;
      ablation.labelled = ablation.labelled && scene.hasLabels();
      for (std::size_t v = 0; v < variants.size(); ++v) {
        ss::SegmentationResult result;
        try {
          result = segmenters[v]->segment(scene);
        } catch (const ss::InputError& error) {
          throw ss::InputError(scene_dir, error.what());
        }
        ablation.totals[v].segments += result.segments.size();
        if (scene.hasLabels()) {
          ablation.totals[v].counts += ss::countMatches(ss::computeOverlap(scene.labels, result.segments), options.sigma);
        }
        if (v == 0) ss::addStageTimes(ablation, base.symmetry.stages, result.timing_ms);
      }
      std::cerr << scene.name << ": " << variants.size() << " stage lists\n";
    }
    ss::printAblationTable(ablation, options.sigma, std::cout);
  }
  return 0;
}

int run(int argc, char** argv) {
  const Options options = parseArguments(argc, argv);
  if (options.help) {
    printUsage(std::cout);
    return 0;
  }
  if (options.scene_arguments.empty())
    throw ss::InputError("no scene directories given (see --help)");
  if (options.ablate) return runAblation(options);
  if (!options.segments_dirs.empty() && (!options.methods.empty() || !options.sweeps.empty()))
    throw ss::InputError("--segments", "cannot be combined with --method or --sweep");

  const std::vector<std::string> scene_dirs = ss::findSceneDirectories(options.scene_arguments);
  // Located before evaluating, so a long sweep does not end in "script not found".
  const std::string plot_script =
      options.plot_path.empty()
          ? std::string()
          : ss::locatePlotScript(options.plot_script, ss::currentExecutablePath(argv[0]));
  std::vector<Run> runs =
      options.segments_dirs.empty() ? planMethodRuns(options) : planSegmentsRuns(options);

  // Scene by scene, so only one scene is in memory at a time.
  std::vector<ss::SceneEvaluation> evaluations;
  for (const std::string& scene_dir : scene_dirs) {
    const ss::Scene scene = ss::loadLabelledScene(scene_dir, options.ground_truth);
    if (!scene.hasLabels())
      throw ss::InputError(scene_dir, "no ground-truth labels (labels.txt, or a label field in the cloud)");
    for (const Run& run : runs) {
      evaluations.push_back(evaluateRun(run, scene, scene_dir));
      const ss::SceneEvaluation& done = evaluations.back();
      const ss::MatchCounts counts = ss::countMatches(done.overlap, options.sigma);
      std::cerr << scene.name << ": " << run.configuration.label() << ": " << counts.segments
                << " segments, " << counts.found_objects << "/" << counts.objects
                << " objects found at sigma " << options.sigma;
      if (done.time_ms >= 0.0) std::cerr << ", " << static_cast<long>(done.time_ms + 0.5) << " ms";
      std::cerr << '\n';
    }
  }

  std::vector<double> sigmas = ss::standardSigmas();
  sigmas.push_back(options.sigma);
  const std::vector<ss::SummaryRow> rows = ss::summarize(evaluations, sigmas);

  std::cout << "Evaluated " << scene_dirs.size() << " scene(s).\n\n";
  ss::printSummaryTables(rows, options.sigma, std::cout);
  ss::printTimingSummary(evaluations, std::cout);

  if (!options.csv_path.empty()) {
    ss::writeSummaryCsvFile(rows, options.csv_path);
    std::cout << "wrote " << options.csv_path << '\n';
  }
  if (!options.plot_path.empty()) {
    writePlot(options, plot_script, rows);
    std::cout << "wrote " << options.plot_path << '\n';
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const ss::InputError& error) {
    std::cerr << "evaluate_segmentation: " << error.what() << '\n';
    return kExitInputError;
  } catch (const std::exception& error) {
    std::cerr << "evaluate_segmentation: " << error.what() << '\n';
    return kExitRuntimeError;
  }
}
