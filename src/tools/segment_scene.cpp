// segment_scene: segments one scene with one method and writes segments.json, a coloured PLY
// and a PNG picture. Exit codes: 0 success, 1 bad input or failure, 2 bad command line.
#include <algorithm>
#include <cstring>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <boost/filesystem.hpp>
#include <pcl/console/print.h>

#include "symmetry_segmentation/command_line.h"
#include "symmetry_segmentation/parameter_schema.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/scene_io.h"
#include "symmetry_segmentation/segmentation_output.h"
#include "symmetry_segmentation/segmenter.h"
#include "symmetry_segmentation/object_box.h"
#include "symmetry_segmentation/segments_json.h"
#include "symmetry_segmentation/stopwatch.h"

namespace ss = symmetry_segmentation;

namespace {

const char* const kUsage =
    "usage: segment_scene <scene> --output DIR [--method M] [--config file.yaml]\n"
    "                     [--set section.key=value]... [--up X,Y,Z] [--no-png]\n"
    "       segment_scene --print-config | --print-live-parameters | --list-stages\n"
    "  <scene>    a scene directory (cloud.ply|cloud.pcd, occupancy.bt, table_plane.txt, labels.txt)\n"
    "             or a single .ply/.pcd cloud file\n"
    "  --method   segmentation method (default: " ;

struct Options {
  std::string scene, output, method = ss::defaultMethod(), config;
  ss::ConfigValues overrides;
  std::optional<Eigen::Vector3f> up;
  bool png = true;
};

void printUsage() {
  std::cout << kUsage << ss::defaultMethod() << "; available:";
  for (const auto& m : ss::availableMethods()) std::cout << ' ' << m;
  std::cout << ")\n  --config   YAML parameter file (see config/default.yaml)\n"
               "  --set      override one parameter, e.g. --set lccp.concavity_tolerance=15 (all --set\n"
               "             values are applied, then the configuration is checked once)\n"
               "  --up X,Y,Z gravity's up in the cloud's frame (e.g. 0,-1,0 for a level camera's optical\n"
               "             frame): the table is then a plane facing up (overrides scene_info.yaml's up)\n"
               "  --no-png   skip the rendered picture\n"
               "  --print-config           print every parameter at its default, documented\n"
               "                           (the text of config/default.yaml), and exit\n"
               "  --print-live-parameters  print the parameters the node takes while it runs\n"
               "                           (the text of cfg/live_parameters.yaml), and exit\n"
               "  --list-stages            print every stage of the symmetry method (kind, what it needs and\n"
               "                           makes, what it does) and the default list, and exit\n";
}

void printStages() {
  auto names = [](const std::vector<ss::Product>& products) {
    std::string text;
    for (ss::Product product : products) text += (text.empty() ? "" : ", ") + std::string(ss::productName(product));
    return text.empty() ? std::string("-") : text;
  };
  for (const ss::StageInfo& stage : ss::stageCatalog()) {
    std::cout << stage.name << " (" << ss::stageKindName(stage.kind) << "; needs " << names(stage.needs) << "; makes "
              << names(stage.makes) << ")\n    " << stage.summary << "\n";
  }
  std::cout << "default symmetry.stages:";
  for (const std::string& name : ss::SymmetryParams().stages) std::cout << ' ' << name;
  std::cout << "\n";
}

Eigen::Vector3f parseUp(const ss::CommandLine& arguments, const std::string& text) {
  Eigen::Vector3f up;
  std::istringstream stream(text);
  char comma1 = 0, comma2 = 0;
  std::string rest;
  if (!(stream >> up.x() >> comma1 >> up.y() >> comma2 >> up.z()) || comma1 != ',' || comma2 != ',' || (stream >> rest)) {
    arguments.usageError("--up wants three numbers X,Y,Z, got '" + text + "'");
  }
  try {
    return ss::checkedUpDirection(up, "--up");
  } catch (const ss::InputError& error) {
    arguments.usageError(error.what());
  }
}

Options parse(int argc, char** argv) {
  Options options;
  ss::CommandLine arguments("segment_scene", argc, argv);
  while (arguments.next()) {
    const std::string arg = arguments.current();
    if (arg == "-h" || arg == "--help") {
      printUsage();
      std::exit(0);
    } else if (arg == "--output" || arg == "-o") {
      options.output = arguments.value();
    } else if (arg == "--method") {
      options.method = arguments.value();
    } else if (arg == "--config") {
      options.config = arguments.value();
    } else if (arg == "--set") {
      options.overrides.push_back(arguments.assignmentValue());
    } else if (arg == "--print-config") {
      std::cout << ss::documentedDefaultConfig();
      std::exit(0);
    } else if (arg == "--print-live-parameters") {
      std::cout << ss::liveParametersYaml();
      std::exit(0);
    } else if (arg == "--list-stages") {
      printStages();
      std::exit(0);
    } else if (arg == "--up") {
      options.up = parseUp(arguments, arguments.value());
    } else if (arg == "--no-png") {
      options.png = false;
    } else if (!arg.empty() && arg[0] == '-') {
      arguments.usageError("unknown option '" + arg + "'");
    } else if (options.scene.empty()) {
      options.scene = arg;
    } else {
      arguments.usageError("unexpected argument '" + arg + "' (one scene at a time)");
    }
  }
  if (options.scene.empty()) arguments.usageError("missing <scene>");
  if (options.output.empty()) arguments.usageError("missing --output DIR");
  return options;
}

std::string formatTimings(const ss::Timings& timings) {
  std::string text;
  char buffer[96];
  for (const auto& [stage, ms] : timings) {
    std::snprintf(buffer, sizeof(buffer), "%s%s %.0f ms", text.empty() ? "" : ", ", stage.c_str(), ms);
    text += buffer;
  }
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  const Options options = parse(argc, argv);
  try {
    const ss::SegmentationConfig config = ss::configWithValues(
        options.config.empty() ? ss::SegmentationConfig{} : ss::loadConfigFile(options.config), options.overrides);
    const auto segmenter = ss::makeSegmenter(options.method, config);

    ss::Stopwatch load_watch;
    ss::Scene scene = ss::loadScene(options.scene);
    if (options.up) scene.up = options.up;
    const double load_ms = load_watch.elapsedMs();
    ss::SegmentationResult result = segmenter->segment(scene);
    result.timing_ms.insert(result.timing_ms.begin(), {"load", load_ms});

    boost::system::error_code ec;
    boost::filesystem::create_directories(options.output, ec);
    if (ec) throw ss::InputError(options.output, "cannot create output directory: " + ec.message());
    const std::string json_path = options.output + "/segments.json";
    const std::string ply_path = options.output + "/segments.ply";
    const std::string png_path = options.output + "/segments.png";
    ss::writeSegmentsJson(result, json_path);
    const auto colored = ss::colorBySegment(*scene.cloud, result.segments);
    ss::writeColoredPly(colored, ply_path);
    const bool completed = std::any_of(result.segments.begin(), result.segments.end(),
                                       [](const ss::Segment& segment) { return segment.completion.has_value(); });
    const std::string completed_path = options.output + "/segments_completed.ply";
    if (completed) ss::writeColoredPly(ss::completedObjects(*scene.cloud, result.segments), completed_path);
    const std::string completed_png_path = options.output + "/segments_completed.png";
    if (options.png) {
      ss::renderPng(colored, ss::defaultView(scene, result.segments), png_path, ss::segmentedPoints(result.segments));
      if (completed) {
        // Each object's added points in a lighter shade of its colour.
        pcl::PointCloud<pcl::PointXYZRGB> with_added = colored;
        with_added += ss::addedPoints(result.segments);
        // Seen from the far side, where the added points are: the sensor's view turned half
        // a turn about the table's up (else the picture's) through its target.
        ss::View far_side = ss::defaultView(scene, result.segments);
        const Eigen::Vector3f up = ss::supportUp(result).value_or(far_side.up.normalized());
        const Eigen::Vector3f offset = far_side.eye - far_side.target;
        const Eigen::Vector3f along_up = offset.dot(up) * up;
        far_side.eye = far_side.target + along_up - (offset - along_up);
        ss::renderPng(with_added, far_side, completed_png_path, ss::segmentedPoints(result.segments));
      }
    }

    std::cout << "scene " << scene.name << ": " << scene.size() << " points, method " << segmenter->name() << ", "
              << result.segments.size() << " segments\n"
              << "time: " << formatTimings(result.timing_ms) << "\n";
    if (!result.counts.empty()) {
      std::cout << "counts:";
      for (const auto& [name, count] : result.counts) std::cout << ' ' << name << ' ' << count;
      std::cout << "\n";
    }
    std::cout
              << "wrote " << json_path << ", " << ply_path << (completed ? ", " + completed_path : "")
              << (options.png ? ", " + png_path : "") << (options.png && completed ? ", " + completed_png_path : "")
              << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "segment_scene: error: " << e.what() << "\n";
    return 1;
  }
}
