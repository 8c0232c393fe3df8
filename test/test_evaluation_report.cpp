// Pooling per kind and overall, the CSV rows, the printed table, and --sweep parsing.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/evaluation/ablation.h"
#include "symmetry_segmentation/evaluation/evaluation_csv.h"
#include "symmetry_segmentation/evaluation/evaluation_summary.h"
#include "symmetry_segmentation/evaluation/evaluation_table.h"
#include "symmetry_segmentation/evaluation/parameter_sweep.h"

namespace ss = symmetry_segmentation;

namespace {

ss::SceneEvaluation sceneEvaluation(const ss::Configuration& configuration, const std::string& scene,
                                    const std::string& kind, const std::vector<int>& labels,
                                    const std::vector<std::vector<int>>& segments, double ms) {
  ss::SceneEvaluation evaluation;
  evaluation.configuration = configuration;
  evaluation.scene = scene;
  evaluation.kind = kind;
  evaluation.overlap = ss::computeOverlap(labels, segments);
  evaluation.time_ms = ms;
  return evaluation;
}

// Scene "a" (kind clutter): 2 objects, both segmented perfectly.
// Scene "b" (no kind): 2 objects; one segment at IoU 0.8 ({0,1,2,3,4} vs object 1 {0,1,2,3}),
// one spurious segment of background points.
std::vector<ss::SceneEvaluation> twoScenes(const ss::Configuration& configuration) {
  return {sceneEvaluation(configuration, "a", "clutter", {1, 1, 2, 2}, {{0, 1}, {2, 3}}, 10.0),
          sceneEvaluation(configuration, "b", "", {1, 1, 1, 1, 0, 0, 2, 2},
                          {{0, 1, 2, 3, 4}, {5}}, 30.0)};
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

}  // namespace

TEST(EvaluationSummary, RowsPerKindThenOverallPooled) {
  const std::vector<ss::SummaryRow> rows =
      ss::summarize(twoScenes({"euclidean", "", ""}), ss::standardSigmas());
  ASSERT_EQ(rows.size(), 9u);  // (clutter, unknown, overall) x 3 sigmas
  EXPECT_EQ(rows[0].kind, "clutter");
  EXPECT_EQ(rows[3].kind, ss::kUnknownKind);
  EXPECT_EQ(rows[6].kind, ss::kOverallKind);
  EXPECT_DOUBLE_EQ(rows[0].sigma, 0.5);
  EXPECT_DOUBLE_EQ(rows[8].sigma, 0.9);

  // Overall at 0.75: segments 4, correct 3; objects 4, found 3.
  const ss::SummaryRow& overall = rows[7];
  EXPECT_DOUBLE_EQ(overall.sigma, 0.75);
  EXPECT_EQ(overall.scenes, 2u);
  EXPECT_EQ(overall.counts.segments, 4u);
  EXPECT_EQ(overall.counts.correct_segments, 3u);
  EXPECT_EQ(overall.counts.found_objects, 3u);
  EXPECT_DOUBLE_EQ(overall.metrics.precision, 0.75);
  EXPECT_DOUBLE_EQ(overall.metrics.recall, 0.75);
  EXPECT_DOUBLE_EQ(overall.metrics.mean_best_iou, (1.0 + 1.0 + 0.8 + 0.0) / 4.0);
  EXPECT_DOUBLE_EQ(overall.mean_time_ms, 20.0);

  // Overall at 0.9: the 0.8 segment no longer counts.
  EXPECT_DOUBLE_EQ(rows[8].metrics.precision, 0.5);
  EXPECT_DOUBLE_EQ(rows[8].metrics.recall, 0.5);
  // Unknown kind at 0.5: P 1/2, R 1/2.
  EXPECT_DOUBLE_EQ(rows[3].metrics.precision, 0.5);
  EXPECT_DOUBLE_EQ(rows[3].metrics.recall, 0.5);
}

TEST(EvaluationSummary, ExtraSigmaIsMergedAndSorted) {
  const std::vector<ss::SummaryRow> rows =
      ss::summarize(twoScenes({"m", "", ""}), {0.9, 0.5, 0.75, 0.5, 0.6});
  ASSERT_EQ(rows.size(), 12u);
  EXPECT_DOUBLE_EQ(rows[1].sigma, 0.6);
}

TEST(EvaluationSummary, BestOverallRowPicksHighestF) {
  std::vector<ss::SceneEvaluation> evaluations;
  // value 1: merges both objects (F 0); value 2: perfect.
  evaluations.push_back(sceneEvaluation({"lccp", "lccp.k", "1"}, "a", "", {1, 1, 2, 2}, {{0, 1, 2, 3}}, 1));
  evaluations.push_back(sceneEvaluation({"lccp", "lccp.k", "2"}, "a", "", {1, 1, 2, 2}, {{0, 1}, {2, 3}}, 1));
  const std::vector<ss::SummaryRow> rows = ss::summarize(evaluations, ss::standardSigmas());
  const ss::SummaryRow* best = ss::bestOverallRow(rows, "lccp", 0.9);
  ASSERT_NE(best, nullptr);
  EXPECT_EQ(best->configuration.parameter_value, "2");
  EXPECT_DOUBLE_EQ(best->metrics.f, 1.0);
  EXPECT_EQ(ss::bestOverallRow(rows, "euclidean", 0.9), nullptr);
}

TEST(EvaluationCsv, OneRowPerConfigurationKindSigma) {
  std::vector<ss::SceneEvaluation> evaluations = twoScenes({"lccp", "lccp.concavity_tolerance", "15"});
  evaluations[1].time_ms = -1.0;  // unknown time: excluded from the mean
  std::ostringstream out;
  ss::writeSummaryCsv(ss::summarize(evaluations, ss::standardSigmas()), out);
  const std::vector<std::string> csv = lines(out.str());
  ASSERT_EQ(csv.size(), 10u);
  EXPECT_EQ(csv[0],
            "method,parameter,value,kind,sigma,scenes,segments,correct_segments,objects,"
            "found_objects,precision,recall,f,mean_best_iou,mean_time_ms");
  EXPECT_EQ(csv[1], "lccp,lccp.concavity_tolerance,15,clutter,0.5,1,2,2,2,2,1.000000,1.000000,"
                    "1.000000,1.000000,10.000");
  EXPECT_EQ(csv[4], "lccp,lccp.concavity_tolerance,15,unknown,0.5,1,2,1,2,1,0.500000,0.500000,"
                    "0.500000,0.400000,");
  EXPECT_EQ(csv[9], "lccp,lccp.concavity_tolerance,15,overall,0.9,2,4,2,4,2,0.500000,0.500000,"
                    "0.500000,0.700000,10.000");
}

TEST(EvaluationCsv, FieldsWithCommasAreQuoted) {
  std::ostringstream out;
  ss::writeSummaryCsv(ss::summarize({sceneEvaluation({"m", "", ""}, "s", "a,\"b\"", {1}, {{0}}, 1)},
                                    {0.5}),
                      out);
  EXPECT_EQ(lines(out.str())[1].rfind("m,,,\"a,\"\"b\"\"\",", 0), 0u) << out.str();
}

TEST(EvaluationCsv, UnwritablePathIsAnInputError) {
  EXPECT_THROW(ss::writeSummaryCsvFile({}, "/nonexistent-dir/x.csv"), ss::InputError);
}

TEST(EvaluationTable, ShowsBestConfigurationPerKindAndSweep) {
  std::vector<ss::SceneEvaluation> evaluations;
  for (const std::string value : {"1", "2"}) {
    for (ss::SceneEvaluation& e : twoScenes({"lccp", "lccp.k", value})) evaluations.push_back(e);
  }
  // Value 2 loses the spurious segment of scene b: better precision, so the best F.
  evaluations[3].overlap.segment_best_iou.pop_back();
  const std::vector<ss::SummaryRow> rows = ss::summarize(evaluations, ss::standardSigmas());
  std::ostringstream out;
  ss::printSummaryTables(rows, 0.9, out);
  const std::string text = out.str();
  EXPECT_NE(text.find("== lccp (lccp.k=2)"), std::string::npos) << text;
  EXPECT_NE(text.find("clutter"), std::string::npos);
  EXPECT_NE(text.find("overall"), std::string::npos);
  EXPECT_NE(text.find("* lccp.k=2"), std::string::npos) << text;
  EXPECT_NE(text.find("  lccp.k=1"), std::string::npos) << text;

  std::ostringstream timing;
  ss::printTimingSummary(evaluations, timing);
  EXPECT_NE(timing.str().find("lccp (lccp.k=1): 2 scenes, mean 20.0, median 20.0, max 30.0 (b)"),
            std::string::npos)
      << timing.str();
}

TEST(ParameterSweep, ParsesKeySectionAndValues) {
  const ss::ParameterSweep sweep = ss::parseSweep("lccp.concavity_tolerance=5, 10,15");
  EXPECT_EQ(sweep.key, "lccp.concavity_tolerance");
  EXPECT_EQ(sweep.section, "lccp");
  EXPECT_EQ(sweep.values, (std::vector<std::string>{"5", "10", "15"}));
  EXPECT_TRUE(ss::sweepAppliesTo(sweep, "lccp"));
  EXPECT_FALSE(ss::sweepAppliesTo(sweep, "euclidean"));
  EXPECT_TRUE(ss::sweepAppliesTo(ss::parseSweep("preprocessing.voxel_size=0.01"), "euclidean"));
}

TEST(ParameterSweep, MalformedSweepsAreInputErrors) {
  for (const char* text : {"lccp.concavity_tolerance", "concavity=5", "lccp.x=", "lccp.x=1,,2",
                           ".x=1", "lccp.=1", "=1"}) {
    EXPECT_THROW(ss::parseSweep(text), ss::InputError) << text;
  }
}

TEST(Ablation, EveryStageTheListCanRunWithoutIsLeftOutOnce) {
  const ss::SymmetryParams params;
  const auto variants = ss::ablationVariants(params.stages);
  ASSERT_FALSE(variants.empty());
  EXPECT_TRUE(variants[0].removed.empty());
  EXPECT_EQ(variants[0].stages, params.stages);
  std::set<std::string> removed;
  for (std::size_t v = 1; v < variants.size(); ++v) {
    EXPECT_TRUE(removed.insert(variants[v].removed).second) << variants[v].removed << " twice";
    EXPECT_EQ(std::count(variants[v].stages.begin(), variants[v].stages.end(), variants[v].removed), 0);
    EXPECT_TRUE(ss::stageListProblems(variants[v].stages).empty()) << variants[v].removed;
  }
  // Both runs of cut and refine go together; what the rest needs is never left out.
  for (const char* required : {"curves", "cut", "islands", "filter"}) EXPECT_EQ(removed.count(required), 0u) << required;
  for (const char* optional : {"refine", "upright", "footprints", "color_seams", "dedup", "object_bottoms"}) {
    EXPECT_EQ(removed.count(optional), 1u) << optional;
  }
}

TEST(Ablation, TheTableShowsTheChangeAgainstTheFullListAndEachStagesTime) {
  ss::DataSetAblation ablation;
  ablation.name = "boxes";
  ablation.scenes = 2;
  ablation.variants = ss::ablationVariants({"curves", "curve_pairs", "cut", "filter", "dedup"});
  ASSERT_EQ(ablation.variants.size(), 2u) << "only dedup can go";
  ablation.totals.resize(2);
  ablation.totals[0].counts = ss::MatchCounts{4, 4, 4, 4, 4.0};   // P = R = 1
  ablation.totals[0].segments = 4;
  ablation.totals[1].counts = ss::MatchCounts{8, 4, 4, 4, 4.0};   // P 0.5, R 1, F 0.667
  ablation.totals[1].segments = 8;
  ss::addStageTimes(ablation, ablation.variants[0].stages,
                    {{"preprocess", 5.0}, {"curves", 10.0}, {"cut", 30.0}, {"dedup", 1.0}, {"total", 50.0}});
  ss::addStageTimes(ablation, ablation.variants[0].stages,
                    {{"preprocess", 5.0}, {"curves", 20.0}, {"cut", 10.0}, {"cut#2", 40.0}, {"dedup", 3.0}, {"total", 90.0}});
  std::ostringstream out;
  ss::printAblationTable(ablation, 0.9, out);
  const std::string table = out.str();
  EXPECT_NE(table.find("Ablation on boxes (2 scenes, 4 objects)"), std::string::npos) << table;
  EXPECT_NE(table.find("| full list | 1.000 | 1.000 | 1.000 |  | 4 | 70.0 (total) |"), std::string::npos) << table;
  EXPECT_NE(table.find("| without dedup | 0.500 | 1.000 | 0.667 | -0.333 | 8 | 2.0 |"), std::string::npos) << table;
  // cut's two runs in the second scene add up: median of 30 and 50.
  EXPECT_NE(table.find("| without cut | (required) | | | | | 40.0 |"), std::string::npos) << table;
}
