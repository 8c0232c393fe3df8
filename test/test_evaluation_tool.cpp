// evaluate_segmentation end to end: a method run on a hand-built scene, stored segments with
// known P/R, the plot, and bad input.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <boost/filesystem.hpp>

#include "test_support.h"

namespace fs = boost::filesystem;
using test_support::makeTempDir;
using test_support::readTextFile;
using test_support::runCommand;
using test_support::toolPath;
using test_support::writeTextFile;

namespace {

struct LabelledPoint {
  float x, y, z;
  int label;
};

void writeScene(const std::string& dir, const std::vector<LabelledPoint>& points,
                const std::string& kind) {
  fs::create_directories(dir);
  std::ostringstream pcd, labels;
  pcd << "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH "
      << points.size() << "\nHEIGHT 1\nVIEWPOINT 0 0 1 1 0 0 0\nPOINTS " << points.size()
      << "\nDATA ascii\n";
  for (const LabelledPoint& p : points) {
    pcd << p.x << ' ' << p.y << ' ' << p.z << '\n';
    labels << p.label << '\n';
  }
  writeTextFile(dir + "/cloud.pcd", pcd.str());
  writeTextFile(dir + "/labels.txt", labels.str());
  if (!kind.empty()) writeTextFile(dir + "/scene_info.yaml", "kind: " + kind + "\n");
}

// A table (label 0) at z = 0 with two 8 cm boxes (labels 1 and 2) 22 cm apart.
std::vector<LabelledPoint> twoBoxesOnTable() {
  std::vector<LabelledPoint> points;
  for (int i = -15; i <= 25; ++i)
    for (int j = -15; j <= 15; ++j) points.push_back({0.02f * i, 0.02f * j, 0.0f, 0});
  const float centres[2] = {0.0f, 0.3f};
  for (int box = 0; box < 2; ++box) {
    // Surface points on a 1 cm grid: the four sides and the top, from 2 cm above the table.
    for (int i = -4; i <= 4; ++i)
      for (int j = -4; j <= 4; ++j)
        for (int k = 2; k <= 10; ++k) {
          const bool surface = i == -4 || i == 4 || j == -4 || j == 4 || k == 10;
          if (surface) points.push_back({centres[box] + 0.01f * i, 0.01f * j, 0.01f * k, box + 1});
        }
  }
  return points;
}

// Tiny scenes for --segments mode; the geometry does not matter there.
std::vector<LabelledPoint> line(const std::vector<int>& labels) {
  std::vector<LabelledPoint> points;
  for (std::size_t i = 0; i < labels.size(); ++i) points.push_back({0.01f * i, 0.0f, 0.0f, labels[i]});
  return points;
}

std::string segmentsJson(std::size_t input_points, const std::vector<std::vector<int>>& segments) {
  std::ostringstream out;
  out << "{\"input_points\": " << input_points << ", \"segments\": [";
  for (std::size_t s = 0; s < segments.size(); ++s) {
    out << (s ? ", " : "") << "{\"indices\": [";
    for (std::size_t i = 0; i < segments[s].size(); ++i) out << (i ? ", " : "") << segments[s][i];
    out << "]}";
  }
  out << "], \"timing_ms\": {\"total\": 12.5}}\n";
  return out.str();
}

void writeFile(const std::string& path, const std::string& content) {
  fs::create_directories(fs::path(path).parent_path());
  writeTextFile(path, content);
}

// CSV rows keyed by (method, value, kind, sigma) -> fields.
using CsvRows = std::map<std::tuple<std::string, std::string, std::string, std::string>,
                         std::vector<std::string>>;

CsvRows readCsv(const std::string& path) {
  CsvRows rows;
  std::istringstream in(readTextFile(path));
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
    if (line.back() == ',') fields.push_back("");
    rows[{fields[0], fields[2], fields[3], fields[4]}] = fields;
  }
  return rows;
}

// Column positions in the CSV.
constexpr int kSegments = 6, kObjects = 8, kPrecision = 10, kRecall = 11, kF = 12, kMeanIou = 13;

bool haveMatplotlib() {
  return runCommand("/usr/bin/python3 -c 'import matplotlib' >/dev/null").exit_code == 0;
}

std::string tool() { return toolPath("evaluate_segmentation"); }

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) result.push_back(line);
  }
  return result;
}

}  // namespace

TEST(EvaluateSegmentationTool, EuclideanFindsBothSeparatedBoxes) {
  const std::string dir = makeTempDir("eval_tool_euclidean");
  writeScene(dir + "/scenes/boxes_1", twoBoxesOnTable(), "boxes");
  writeTextFile(dir + "/scenes/boxes_1/table_plane.txt", "0 0 1 0\n");
  const std::string csv = dir + "/out.csv";

  const auto result =
      runCommand(tool() + " " + dir + "/scenes --method euclidean --csv " + csv);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("== euclidean"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("timing"), std::string::npos) << result.output;

  const CsvRows rows = readCsv(csv);
  const auto overall = rows.find({"euclidean", "", "overall", "0.5"});
  ASSERT_NE(overall, rows.end()) << readTextFile(csv);
  EXPECT_EQ(overall->second[kObjects], "2");
  EXPECT_EQ(overall->second[kRecall], "1.000000") << readTextFile(csv);
  EXPECT_EQ(overall->second[kPrecision], "1.000000") << readTextFile(csv);
  EXPECT_NE(rows.find({"euclidean", "", "boxes", "0.9"}), rows.end()) << readTextFile(csv);
}

TEST(EvaluateSegmentationTool, AblateRunsTheSymmetryMethodWithoutEachStage) {
  const std::string dir = makeTempDir("eval_tool_ablate");
  writeScene(dir + "/scenes/boxes_1", twoBoxesOnTable(), "boxes");
  writeTextFile(dir + "/scenes/boxes_1/table_plane.txt", "0 0 1 0\n");
  // A scene without labels (a real scan, say) is a data set of its own: segment counts only.
  writeScene(dir + "/unlabelled", twoBoxesOnTable(), "");
  writeTextFile(dir + "/unlabelled/table_plane.txt", "0 0 1 0\n");
  fs::remove(dir + "/unlabelled/labels.txt");

  const auto result = runCommand(tool() + " " + dir + "/scenes " + dir + "/unlabelled --ablate");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  EXPECT_NE(result.output.find("Ablation on scenes (1 scene, 2 objects)"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("Ablation on unlabelled (1 scene)"), std::string::npos) << result.output;
  std::size_t rows = 0, required = 0;
  for (const std::string& row : lines(result.output)) {
    if (row.rfind("| without ", 0) != 0) continue;
    ++rows;
    if (row.find("(required)") != std::string::npos) ++required;
  }
  EXPECT_EQ(rows, 2u * 18u) << "a row per stage of the default list, per data set";
  EXPECT_EQ(required, 2u * 4u) << "curves, cut, islands, filter";

  const auto lccp = runCommand(tool() + " " + dir + "/scenes --ablate --method lccp");
  EXPECT_EQ(lccp.exit_code, 2);
  EXPECT_NE(lccp.output.find("symmetry method only"), std::string::npos) << lccp.output;
}

TEST(EvaluateSegmentationTool, SweepWritesOneRowPerValueAndAPlot) {
  const std::string dir = makeTempDir("eval_tool_sweep");
  writeScene(dir + "/boxes", twoBoxesOnTable(), "");
  writeTextFile(dir + "/boxes/table_plane.txt", "0 0 1 0\n");
  const std::string csv = dir + "/sweep.csv", png = dir + "/pr.png";
  const bool plot = haveMatplotlib();

  const auto result =
      runCommand(tool() + " " + dir + "/boxes --method euclidean --sweep " +
                 "euclidean.cluster_tolerance=0.02,0.5 --csv " + csv + (plot ? " --plot " + png : ""));
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const CsvRows rows = readCsv(csv);
  // 2 values x (unknown kind + overall) x 3 sigmas.
  EXPECT_EQ(rows.size(), 12u) << readTextFile(csv);
  const auto narrow = rows.find({"euclidean", "0.02", "overall", "0.9"});
  const auto wide = rows.find({"euclidean", "0.5", "overall", "0.9"});
  ASSERT_NE(narrow, rows.end());
  ASSERT_NE(wide, rows.end());
  EXPECT_EQ(narrow->second[1], "euclidean.cluster_tolerance");
  // A 50 cm tolerance merges the two boxes into one segment: nothing is found.
  EXPECT_EQ(wide->second[kSegments], "1") << readTextFile(csv);
  EXPECT_EQ(wide->second[kRecall], "0.000000");
  EXPECT_NE(result.output.find("* euclidean.cluster_tolerance=0.02"), std::string::npos)
      << result.output;

  if (!plot) GTEST_SKIP() << "matplotlib not available for /usr/bin/python3";
  ASSERT_TRUE(fs::exists(png)) << result.output;
  EXPECT_GT(fs::file_size(png), 1000u);
  EXPECT_EQ(readTextFile(png).substr(1, 3), "PNG");
}

TEST(EvaluateSegmentationTool, StoredSegmentsGiveHandComputedMetrics) {
  const std::string dir = makeTempDir("eval_tool_segments");
  // s1: objects 1 {0-3}, 2 {4-7}; segments {0-3} (IoU 1) and {4,5} (IoU 0.5, not > 0.5).
  writeScene(dir + "/scenes/s1", line({1, 1, 1, 1, 2, 2, 2, 2}), "clutter");
  writeFile(dir + "/segs/s1/segments.json", segmentsJson(8, {{0, 1, 2, 3}, {4, 5}}));
  // s2: object 3 {2,3}; segments {2,3} (IoU 1) and {0} (background). Flat file layout.
  writeScene(dir + "/scenes/s2", line({0, 0, 3, 3}), "");
  writeFile(dir + "/segs/s2.json", segmentsJson(4, {{2, 3}, {0}}));
  const std::string csv = dir + "/out.csv";

  const auto result =
      runCommand(tool() + " " + dir + "/scenes --segments " + dir + "/segs --csv " + csv);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  const CsvRows rows = readCsv(csv);

  // Pooled: segments 4, correct 2 -> P 1/2; objects 3, found 2 -> R 2/3; F = 4/7.
  const auto overall = rows.find({"segs", "", "overall", "0.5"});
  ASSERT_NE(overall, rows.end()) << readTextFile(csv);
  EXPECT_EQ(overall->second[kPrecision], "0.500000");
  EXPECT_EQ(overall->second[kRecall], "0.666667");
  EXPECT_EQ(overall->second[kF], "0.571429");
  EXPECT_EQ(overall->second[kMeanIou], "0.833333");  // (1 + 0.5 + 1) / 3
  EXPECT_EQ(overall->second.back(), "12.500");

  const auto clutter = rows.find({"segs", "", "clutter", "0.5"});
  ASSERT_NE(clutter, rows.end());
  EXPECT_EQ(clutter->second[kRecall], "0.500000");
  const auto unknown = rows.find({"segs", "", "unknown", "0.5"});
  ASSERT_NE(unknown, rows.end());
  EXPECT_EQ(unknown->second[kRecall], "1.000000");
  // At 0.9 nothing changes for these IoUs (1 or <= 0.5).
  EXPECT_EQ(rows.at({"segs", "", "overall", "0.9"})[kF], "0.571429");
}

TEST(EvaluateSegmentationTool, BadInputExitsWithOneLineError) {
  const std::string dir = makeTempDir("eval_tool_errors");
  writeScene(dir + "/good", line({1, 1, 2, 2}), "");
  writeFile(dir + "/segs/good/segments.json", segmentsJson(4, {{0, 1}}));
  writeFile(dir + "/mismatch/good/segments.json", segmentsJson(5, {{0, 1}}));
  writeFile(dir + "/broken/good/segments.json", "{\"input_points\": 4, \"segm");
  fs::create_directories(dir + "/missing");
  fs::create_directories(dir + "/unlabelled");
  writeTextFile(dir + "/unlabelled/cloud.pcd", "not read");
  const std::string good = dir + "/good";

  struct Case {
    std::string arguments;
    std::string expected;  // part of the message
  };
  const std::vector<Case> cases = {
      {"", "no scene directories"},
      {dir + "/nonexistent", dir + "/nonexistent: no such file"},
      {dir + "/unlabelled", "no labels.txt"},
      {good + " --method nosuchmethod", "unknown method 'nosuchmethod'"},
      {good + " --method euclidean --sweep euclidean.cluster_tolerance", "--sweep"},
      {good + " --method euclidean --sweep lccp.concavity_tolerance=5", "none of the methods"},
      {good + " --method euclidean --sweep euclidean.no_such_key=1", "no_such_key"},
      {good + " --segments " + dir + "/missing", "no segments for scene 'good'"},
      {good + " --segments " + dir + "/mismatch", "input_points 5 does not match"},
      {good + " --segments " + dir + "/broken", dir + "/broken/good/segments.json"},
      {good + " --segments " + dir + "/segs --method euclidean", "cannot be combined"},
      {good + " --segments " + dir + "/segs --plot " + dir + "/x.png --plot-script " + dir +
           "/none.py",
       "plot script not found"},
      {good + " --bogus", "--bogus: unknown option"},
      {good + " --csv", "--csv: missing value"},
      {good + " --sigma 2", "--sigma"},
      {good + " --config " + dir + "/none.yaml", "none.yaml"},
  };
  for (const Case& c : cases) {
    const auto result = runCommand(tool() + " " + c.arguments);
    EXPECT_EQ(result.exit_code, 2) << c.arguments << "\n" << result.output;
    // The error is the tool's last line, and one line (PCL may warn before it on stderr).
    const std::vector<std::string> output = lines(result.output);
    ASSERT_FALSE(output.empty()) << c.arguments;
    EXPECT_EQ(output.back().rfind("evaluate_segmentation: ", 0), 0u) << result.output;
    EXPECT_NE(output.back().find(c.expected), std::string::npos) << c.arguments << "\n"
                                                                 << result.output;
  }
}

TEST(EvaluateSegmentationTool, HelpDescribesOptions) {
  const auto result = runCommand(tool() + " --help");
  EXPECT_EQ(result.exit_code, 0);
  for (const char* option : {"--method", "--segments", "--sweep", "--csv", "--plot", "--sigma",
                             "--plot-script", "Exit status"}) {
    EXPECT_NE(result.output.find(option), std::string::npos) << option;
  }
}

TEST(PlotPrecisionRecallScript, WritesPngFromCsv) {
  if (!haveMatplotlib()) GTEST_SKIP() << "matplotlib not available for /usr/bin/python3";
  const std::string dir = makeTempDir("eval_plot_script");
  writeTextFile(dir + "/in.csv",
                "method,parameter,value,kind,sigma,scenes,segments,correct_segments,objects,"
                "found_objects,precision,recall,f,mean_best_iou,mean_time_ms\n"
                "lccp,lccp.concavity_tolerance,5,overall,0.9,1,4,2,4,2,0.5,0.5,0.5,0.6,1\n"
                "lccp,lccp.concavity_tolerance,10,overall,0.9,1,4,3,4,3,0.75,0.75,0.75,0.8,1\n"
                "euclidean,,,overall,0.9,1,4,1,4,1,0.25,0.25,0.25,0.4,\n");
  const std::string script = test_support::sourceDir() + "/scripts/plot_precision_recall.py";
  const auto ok = runCommand("/usr/bin/python3 " + script + " " + dir + "/in.csv --output " + dir +
                             "/out.png --sigma 0.9");
  ASSERT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_GT(fs::file_size(dir + "/out.png"), 1000u);

  // No rows at the requested sigma: an error, not an empty plot.
  const auto none = runCommand("/usr/bin/python3 " + script + " " + dir + "/in.csv --output " +
                               dir + "/none.png --sigma 0.5");
  EXPECT_EQ(none.exit_code, 2) << none.output;
  EXPECT_NE(none.output.find("no rows"), std::string::npos) << none.output;
}

// evaluate_completion on a scene make_scene wrote (with its objects' whole shapes), and on
// scenes without them.
TEST(EvaluateCompletion, ReportsScenesWithWholeShapesAndRejectsOthers) {
  const std::string dir = makeTempDir("evaluate_completion");
  const auto made = runCommand(toolPath("make_scene") + " --kind isolated --seed 4 --output " + dir + "/isolated_4");
  ASSERT_EQ(made.exit_code, 0) << made.output;
  ASSERT_TRUE(fs::exists(dir + "/isolated_4/objects.yaml"));
  ASSERT_TRUE(fs::exists(dir + "/isolated_4/objects_surface.ply"));
  const auto result = runCommand(toolPath("evaluate_completion") + " " + dir + " --csv " + dir + "/objects.csv");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::istringstream lines(result.output);
  std::string line;
  bool overall = false;
  int overall_objects = 0;
  while (std::getline(lines, line)) {
    if (line.rfind("overall", 0) != 0) continue;
    overall = true;
    std::string name, bar;
    int scenes = 0, objects = 0;
    double iou_visible = 0, iou_completed = 0;
    std::istringstream row(line);
    row >> name >> scenes >> objects >> bar >> iou_visible >> iou_completed;
    EXPECT_EQ(scenes, 1);
    EXPECT_GE(objects, 3);  // 3-5 objects well apart, most found
    overall_objects = objects;
    EXPECT_GT(iou_visible, 0.5);
    EXPECT_GT(iou_completed, 0.5);
  }
  EXPECT_TRUE(overall) << result.output;
  // One CSV row per scored object, naming its scene and shape, its figures in range.
  std::ifstream csv(dir + "/objects.csv");
  std::string header;
  ASSERT_TRUE(std::getline(csv, header));
  EXPECT_EQ(header.rfind("scene,kind,label,shape,segment_iou,", 0), 0u) << header;
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    std::vector<std::string> fields;
    std::istringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    ASSERT_EQ(fields.size(), 10u) << line;
    EXPECT_EQ(fields[0], "isolated_4");
    EXPECT_EQ(fields[1], "isolated");
    EXPECT_FALSE(fields[3].empty()) << line;
    EXPECT_GT(std::stod(fields[4]), 0.5) << line;
    EXPECT_LE(std::stod(fields[6]), 1.0) << line;
  }
  EXPECT_EQ(rows, overall_objects);

  writeScene(dir + "/labelled_only", twoBoxesOnTable(), "");
  const auto none = runCommand(toolPath("evaluate_completion") + " " + dir + "/labelled_only");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.output.find("no scene with objects.yaml"), std::string::npos) << none.output;
  writeTextFile(dir + "/no_completion.yaml", "symmetry:\n  stages: [curves, curve_pairs, cut, refine, filter, dedup]\n");
  const auto off = runCommand(toolPath("evaluate_completion") + " " + dir + "/isolated_4 --config " + dir + "/no_completion.yaml");
  EXPECT_EQ(off.exit_code, 2);
  EXPECT_NE(off.output.find("no 'completion'"), std::string::npos) << off.output;
}
