// The quality harness end to end: the fixed synthetic test set, both baselines through
// evaluate_segmentation, and checks that the numbers mean what they should.
#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "test_support.h"

namespace {

struct Row {
  double precision = 0, recall = 0, f = 0;
  int objects = 0;
};

// key: method/kind/sigma (sigma as printed in the CSV)
std::map<std::string, Row> readCsv(const std::string& path) {
  std::map<std::string, Row> rows;
  std::istringstream lines(test_support::readTextFile(path));
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line.rfind("method,parameter,value,kind,sigma,scenes,segments,correct_segments,objects,found_objects,"
                       "precision,recall,f",
                       0),
            0u)
      << line;
  while (std::getline(lines, line)) {
    std::vector<std::string> cells;
    std::stringstream cell_stream(line);
    std::string cell;
    while (std::getline(cell_stream, cell, ',')) cells.push_back(cell);
    if (cells.size() < 13) continue;
    Row row;
    row.objects = std::stoi(cells[8]);
    row.precision = std::stod(cells[10]);
    row.recall = std::stod(cells[11]);
    row.f = std::stod(cells[12]);
    rows[cells[0] + "/" + cells[3] + "/" + cells[4]] = row;
  }
  return rows;
}

}  // namespace

TEST(QualityHarness, BaselinesOnTheGeneratedSet) {
  const std::string dir = test_support::makeTempDir("quality_harness");
  const auto generated = test_support::runCommand(test_support::sourceDir() + "/scripts/make_test_scenes " + dir +
                                                  "/scenes " + test_support::toolPath("make_scene"));
  ASSERT_EQ(generated.exit_code, 0) << generated.output;
  const auto evaluated = test_support::runCommand(test_support::toolPath("evaluate_segmentation") + " " + dir +
                                                  "/scenes --method symmetry --method euclidean --method lccp --csv " + dir +
                                                  "/eval.csv");
  std::cout << evaluated.output << std::endl;  // the table, for the log
  ASSERT_EQ(evaluated.exit_code, 0) << evaluated.output;

  const auto rows = readCsv(dir + "/eval.csv");
  for (const char* method : {"symmetry", "euclidean", "lccp"}) {
    for (const char* kind : {"isolated", "touching", "stacked", "occluded", "nonconvex", "clutter", "overall"}) {
      for (const char* sigma : {"0.5", "0.75", "0.9"}) {
        const std::string key = std::string(method) + "/" + kind + "/" + sigma;
        ASSERT_TRUE(rows.count(key)) << key;
        EXPECT_GT(rows.at(key).objects, 0) << key;
      }
    }
  }
  // Well-separated objects are what Euclidean clustering is for: nearly all must be found.
  EXPECT_GE(rows.at("euclidean/isolated/0.9").recall, 0.8);
  EXPECT_GE(rows.at("lccp/isolated/0.5").recall, 0.7);
  // Objects pushed together defeat it: that is why the other kinds exist.
  EXPECT_LT(rows.at("euclidean/touching/0.5").recall, rows.at("euclidean/isolated/0.5").recall);
  EXPECT_LT(rows.at("euclidean/stacked/0.5").recall, rows.at("euclidean/isolated/0.5").recall);
  // The symmetry method (default, paper-strict thresholds) finds nearly all well-separated
  // objects roughly and about half of all objects exactly. Round objects have few normal
  // edges: before the upright hypotheses these were 0.75 and 0.40.
  EXPECT_GE(rows.at("symmetry/isolated/0.5").recall, 0.85);
  EXPECT_GE(rows.at("symmetry/overall/0.5").precision, 0.85);
  EXPECT_GE(rows.at("symmetry/overall/0.9").f, 0.5);
  // Stricter thresholds can only lose matches.
  for (const char* method : {"symmetry", "euclidean", "lccp"}) {
    const std::string prefix = std::string(method) + "/overall/";
    EXPECT_LE(rows.at(prefix + "0.9").recall, rows.at(prefix + "0.75").recall);
    EXPECT_LE(rows.at(prefix + "0.75").recall, rows.at(prefix + "0.5").recall);
  }
}
