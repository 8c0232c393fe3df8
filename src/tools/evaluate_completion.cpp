// evaluate_completion: how well each correctly segmented object, completed by its symmetry
// (stage completion), stands for the whole object, against its visible points alone.
// Exit codes: 0 success, 1 failure, 2 bad command line or input.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <pcl/console/print.h>

#include "symmetry_segmentation/command_line.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/evaluation/completion_metric.h"
#include "symmetry_segmentation/evaluation/evaluation_inputs.h"
#include "symmetry_segmentation/scene_io.h"
#include "symmetry_segmentation/segmentation_config.h"
#include "symmetry_segmentation/segmenter.h"

namespace ss = symmetry_segmentation;

namespace {

struct Options {
  std::vector<std::string> scenes;
  std::string config;
  std::string csv;
};

Options parse(int argc, char** argv) {
  Options options;
  ss::CommandLine arguments("evaluate_completion", argc, argv);
  while (arguments.next()) {
    const std::string arg = arguments.current();
    if (arg == "-h" || arg == "--help") {
      std::cout << "usage: evaluate_completion <scene_dir>... [--config FILE] [--csv FILE]\n"
                   "Runs the symmetry method on scenes made by make_scene (objects.yaml and objects_surface.ply\n"
                   "hold each object's whole shape) and reports per scene kind, for the objects a segment\n"
                   "overlaps with IoU > 0.5: the median IoU of the segment's box with the object's true box and\n"
                   "the median symmetric Chamfer distance of its points to the true surface (every side but the\n"
                   "base), for the visible points alone and completed by the object's symmetry (stage\n"
                   "completion; it must be in symmetry.stages). Each <scene_dir> is a scene or a directory of\n"
                   "scenes; scenes without objects.yaml are skipped. --csv FILE writes one row per object (scene,\n"
                   "kind, label, shape, segment IoU, box IoUs, Chamfer in mm, points added) for a closer look.\n";
      std::exit(0);
    } else if (arg == "--config") {
      options.config = arguments.value();
    } else if (arg == "--csv") {
      options.csv = arguments.value();
    } else if (!arg.empty() && arg[0] == '-') {
      arguments.usageError("unknown option '" + arg + "'");
    } else {
      options.scenes.push_back(arg);
    }
  }
  if (options.scenes.empty()) arguments.usageError("no scene given");
  return options;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

void printRow(const std::string& kind, std::size_t scenes, const std::vector<ss::CompletionScore>& scores) {
  std::vector<double> iou_visible, iou_completed, chamfer_visible, chamfer_completed;
  for (const auto& score : scores) {
    iou_visible.push_back(score.box_iou_visible);
    iou_completed.push_back(score.box_iou_completed);
    chamfer_visible.push_back(1000.0 * score.chamfer_visible);
    chamfer_completed.push_back(1000.0 * score.chamfer_completed);
  }
  if (scores.empty()) {  // no object to take a median of: no figure, not a perfect one
    std::printf("%-12s %6zu %7zu | %7s %9s | %8s %10s\n", kind.c_str(), scenes, scores.size(), "-", "-", "-", "-");
    return;
  }
  std::printf("%-12s %6zu %7zu | %7.3f %9.3f | %8.1f %10.1f\n", kind.c_str(), scenes, scores.size(), median(iou_visible),
              median(iou_completed), median(chamfer_visible), median(chamfer_completed));
}

}  // namespace

int main(int argc, char** argv) {
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  const Options options = parse(argc, argv);
  try {
    const ss::SegmentationConfig config =
        options.config.empty() ? ss::SegmentationConfig{} : ss::loadConfigFile(options.config);
    const auto& stages = config.symmetry.stages;
    if (std::find(stages.begin(), stages.end(), "completion") == stages.end()) {
      throw ss::InputError(options.config, "symmetry.stages has no 'completion': nothing to evaluate");
    }
    const auto segmenter = ss::makeSegmenter("symmetry", config);
    std::map<std::string, std::vector<ss::CompletionScore>> by_kind;
    std::map<std::string, std::size_t> scenes_by_kind;
    std::vector<ss::CompletionScore> all;
    std::size_t scenes = 0;
    std::ofstream csv;
    if (!options.csv.empty()) {
      csv.open(options.csv);
      if (!csv) throw ss::InputError(options.csv, "cannot write");
      csv << "scene,kind,label,shape,segment_iou,box_iou_visible,box_iou_completed,chamfer_visible_mm,"
             "chamfer_completed_mm,added_points\n";
    }
    for (const std::string& directory : ss::findSceneDirectories(options.scenes)) {
      const std::vector<ss::TrueShape> shapes = ss::loadTrueShapes(directory);
      if (shapes.empty()) continue;
      const ss::Scene scene = ss::loadScene(directory);
      const ss::SegmentationResult result = segmenter->segment(scene);
      const std::vector<ss::CompletionScore> scores = ss::scoreCompletion(scene, result, shapes);
      const std::string kind = scene.kind.empty() ? "unknown" : scene.kind;
      by_kind[kind].insert(by_kind[kind].end(), scores.begin(), scores.end());
      ++scenes_by_kind[kind];
      all.insert(all.end(), scores.begin(), scores.end());
      if (csv.is_open()) {
        for (const auto& score : scores) {
          csv << scene.name << ',' << kind << ',' << score.label << ',' << score.shape << ',' << score.segment_iou << ','
              << score.box_iou_visible << ',' << score.box_iou_completed << ',' << 1000.0 * score.chamfer_visible << ','
              << 1000.0 * score.chamfer_completed << ',' << score.added_points << '\n';
        }
      }
      ++scenes;
      std::cerr << "evaluate_completion: " << scene.name << ": " << scores.size() << " objects\n";
    }
    if (scenes == 0) throw ss::InputError(options.scenes.front(), "no scene with objects.yaml (made by make_scene)");
    std::printf("Completion of correctly segmented objects (segment IoU > 0.5), medians; visible = the\n"
                "segment's points and box, completed = with its reflections into unobserved space.\n\n");
    std::printf("%-12s %6s %7s | %7s %9s | %8s %10s\n", "kind", "scenes", "objects", "box IoU", "", "Chamfer", "mm");
    std::printf("%-12s %6s %7s | %7s %9s | %8s %10s\n", "", "", "", "visible", "completed", "visible", "completed");
    for (const auto& [kind, scores] : by_kind) printRow(kind, scenes_by_kind[kind], scores);
    printRow("overall", scenes, all);
    if (csv.is_open() && !csv.flush()) throw ss::InputError(options.csv, "cannot write");
    return 0;
  } catch (const ss::InputError& e) {
    std::cerr << "evaluate_completion: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "evaluate_completion: error: " << e.what() << "\n";
    return 1;
  }
}
