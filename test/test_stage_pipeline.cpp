// The symmetry method as a list of stages: the list is checked before anything runs, each stage
// is timed and counted under its own name, a stage runs alone on a state built by hand, and the
// default list keeps giving the segments it gave (a golden file of segment fingerprints).
#include <gtest/gtest.h>

#include <boost/filesystem.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <regex>
#include <sstream>

#include "fake_evidence.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/scene_io.h"
#include "symmetry_segmentation/segmenter.h"
#include "symmetry_segmentation/symmetry/duplicate_segments.h"
#include "symmetry_segmentation/symmetry/nested_segments.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stage.h"
#include "symmetry_segmentation/synthetic/scene_generator.h"
#include "test_support.h"

namespace ss = symmetry_segmentation;

namespace {

std::string problemsOf(const std::vector<std::string>& stages) {
  std::string all;
  for (const std::string& problem : ss::stageListProblems(stages)) all += problem + "\n";
  return all;
}

ss::CandidateSegment candidate(int first, int last, float occlusion, float smoothness) {
  ss::CandidateSegment segment;
  for (int i = first; i <= last; ++i) segment.points.push_back(i);
  segment.scores = {occlusion, smoothness};
  return segment;
}

}  // namespace

TEST(StageList, TheDefaultListRunsAndEveryStageIsInTheCatalog) {
  const ss::SymmetryParams params;
  EXPECT_TRUE(ss::stageListProblems(params.stages).empty()) << problemsOf(params.stages);
  for (const std::string& name : params.stages) EXPECT_NE(ss::findStage(name), nullptr) << name;
  // The default list runs the catalog's stages in the catalog's order; a catalog stage left out
  // of it (one that did not earn its place) is optional.
  std::vector<std::string> first_runs;
  for (const std::string& name : params.stages) {
    if (std::find(first_runs.begin(), first_runs.end(), name) == first_runs.end()) first_runs.push_back(name);
  }
  std::vector<std::string> catalog_in_default;
  for (const ss::StageInfo& stage : ss::stageCatalog()) {
    if (std::find(first_runs.begin(), first_runs.end(), stage.name) != first_runs.end()) {
      catalog_in_default.push_back(stage.name);
    }
  }
  EXPECT_EQ(first_runs, catalog_in_default);
  EXPECT_LE(ss::stageCatalog().size() - first_runs.size(), 2u) << "optional stages: say why in their headers";
}

TEST(StageList, EachStageHeaderNamesItsPlaceInTheDefaultList) {
  // "// Stage N, name ..." on the second line of exactly one header per stage of the default
  // list, N its first position there: the headers read in the order the stages run. A catalog
  // stage out of the default list says so: "// Optional stage name ...".
  const ss::SymmetryParams params;
  std::map<std::string, int> labelled;  // 0: optional
  const std::regex label("^// (?:Stage (\\d+),|Optional stage) (\\w+)");
  for (const auto& entry : boost::filesystem::directory_iterator(test_support::sourceDir() +
                                                                 "/include/symmetry_segmentation/symmetry")) {
    std::istringstream header(test_support::readTextFile(entry.path().string()));
    std::string line;
    std::getline(header, line);
    std::getline(header, line);
    std::smatch match;
    if (!std::regex_search(line, match, label)) continue;
    EXPECT_EQ(labelled.count(match[2]), 0u) << match[2] << " labelled twice";
    labelled[match[2]] = match[1].matched ? std::stoi(match[1]) : 0;
  }
  for (const ss::StageInfo& stage : ss::stageCatalog()) {
    ASSERT_EQ(labelled.count(stage.name), 1u) << "no header labelled 'Stage N, " << stage.name << "'";
    const auto first = std::find(params.stages.begin(), params.stages.end(), stage.name);
    const int expected = first == params.stages.end() ? 0 : static_cast<int>(first - params.stages.begin() + 1);
    EXPECT_EQ(labelled[stage.name], expected) << stage.name;
  }
  EXPECT_EQ(labelled.size(), ss::stageCatalog().size());
}

TEST(StageList, TheReadmeListsTheDefaultListInOrder) {
  // "N. `name` ..." items of the README's method section, one per entry of the default list.
  const std::string readme = test_support::readTextFile(test_support::sourceDir() + "/README.md");
  const std::size_t begin = readme.find("## The symmetry method");
  ASSERT_NE(begin, std::string::npos);
  std::istringstream section(readme.substr(begin, readme.find("\n## ", begin + 1) - begin));
  std::vector<std::string> listed;
  const std::regex item("^(\\d+)\\. `(\\w+)`");
  for (std::string line; std::getline(section, line);) {
    std::smatch match;
    if (!std::regex_search(line, match, item)) continue;
    EXPECT_EQ(std::stoul(match[1]), listed.size() + 1) << line;
    listed.push_back(match[2]);
  }
  EXPECT_EQ(listed, ss::SymmetryParams().stages);
}

TEST(StageList, AListThatCannotRunIsRejectedWithItsReason) {
  EXPECT_NE(problemsOf({"curves", "curve_pairs", "cut", "filter", "no_such_stage"}).find("unknown stage 'no_such_stage'"),
            std::string::npos);
  // cut before any hypothesis source: nothing to cut.
  EXPECT_NE(problemsOf({"cut", "curves", "curve_pairs", "filter"}).find("'cut' (position 1) needs hypotheses"),
            std::string::npos);
  // upright needs the surfaces the curves stage makes.
  EXPECT_NE(problemsOf({"upright", "cut", "filter"}).find("'upright' (position 1) needs surfaces"), std::string::npos);
  // Nothing turns candidates into segments.
  EXPECT_NE(problemsOf({"curves", "curve_pairs", "cut"}).find("no stage makes the segments"), std::string::npos);
  // Hypotheses added after the last cut would never be cut.
  EXPECT_NE(problemsOf({"curves", "curve_pairs", "cut", "islands", "footprints", "filter"}).find("no later 'cut'"),
            std::string::npos);
  EXPECT_TRUE(ss::stageListProblems({"curves", "curve_pairs", "cut", "filter"}).empty());
  // occluder_gaps adds candidates aligned with their hypotheses: nothing may wait for a cut.
  EXPECT_NE(problemsOf({"curves", "curve_pairs", "cut", "islands", "footprints", "occluder_gaps", "cut", "filter"})
                .find("'occluder_gaps' (position 6) needs every earlier hypothesis cut"),
            std::string::npos);
  EXPECT_TRUE(ss::stageListProblems({"curves", "curve_pairs", "cut", "occluder_gaps", "refine", "filter"}).empty());
  // completion describes the final segments: nothing may change them after it.
  EXPECT_NE(problemsOf({"curves", "curve_pairs", "cut", "filter", "completion", "dedup"})
                .find("'completion' (position 5) describes the final segments"),
            std::string::npos);
  EXPECT_TRUE(ss::stageListProblems({"curves", "curve_pairs", "cut", "filter", "dedup", "completion"}).empty());

  // The configuration rejects such a list as a whole and keeps the previous one.
  ss::SegmentationConfig config;
  const auto before = config.symmetry.stages;
  EXPECT_THROW(ss::setConfigValue(config, "symmetry.stages", "[cut, filter]"), ss::InputError);
  EXPECT_EQ(config.symmetry.stages, before);
  ss::setConfigValue(config, "symmetry.stages", "[curves, curve_pairs, cut, refine, filter, dedup]");
  EXPECT_EQ(config.symmetry.stages.size(), 6u);
  EXPECT_THROW(ss::setConfigValue(config, "symmetry.stages", "cut"), ss::InputError) << "a list, not a name";
}

TEST(StagePipeline, EachStageIsTimedAndCountedUnderItsOwnName) {
  ss::synthetic::GeneratorOptions options;
  options.kind = ss::synthetic::SceneKind::Isolated;
  options.seed = 1;
  const ss::Scene scene = ss::synthetic::generateScene(options);
  const ss::SegmentationConfig config;
  const ss::SegmentationResult result = ss::makeSegmenter("symmetry", config)->segment(scene);

  std::vector<std::string> timed;
  for (const auto& [name, ms] : result.timing_ms) timed.push_back(name);
  std::vector<std::string> expected = {"preprocess", "occupancy", "graph"};
  std::map<std::string, int> runs;
  for (const std::string& stage : config.symmetry.stages) {
    const int run = ++runs[stage];
    expected.push_back(run == 1 ? stage : stage + "#" + std::to_string(run));
  }
  expected.push_back("total");
  EXPECT_EQ(timed, expected);
  // Every stage counts something under its label.
  for (std::size_t i = 3; i + 1 < expected.size(); ++i) {
    const bool counted = std::any_of(result.counts.begin(), result.counts.end(), [&](const auto& count) {
      return count.first.rfind(expected[i] + ".", 0) == 0;
    });
    EXPECT_TRUE(counted) << expected[i];
  }
}

TEST(StagePipeline, AStageLeftOutOfTheListDoesNotRun) {
  ss::synthetic::GeneratorOptions options;
  options.kind = ss::synthetic::SceneKind::Stacked;
  options.seed = 1;
  const ss::Scene scene = ss::synthetic::generateScene(options);
  ss::SegmentationConfig config;
  auto& stages = config.symmetry.stages;
  stages.erase(std::remove(stages.begin(), stages.end(), "color_seams"), stages.end());
  const ss::SegmentationResult result = ss::makeSegmenter("symmetry", config)->segment(scene);
  for (const auto& [name, count] : result.counts) EXPECT_EQ(name.find("color_seams"), std::string::npos) << name;
  for (const auto& [name, ms] : result.timing_ms) EXPECT_NE(name, "color_seams");
}

TEST(StagePipeline, AStageRunsAloneOnAStateBuiltByHand) {
  // filter, then nested, then dedup on three candidates over 100 fake points.
  ss::PipelineState state;
  auto evidence = std::make_unique<test_support::FakeEvidence>(100);
  // The large segment's plane (distance 1) explains only points below 60.
  evidence->lands_on = [](int index, const ss::SymmetryPlane& plane) {
    return plane.distance == 1.0f && index >= 60 ? -1 : index;
  };
  state.evidence = std::move(evidence);
  state.candidates = {candidate(0, 99, 1.0f, 0.0f), candidate(60, 89, 1.0f, 0.01f), candidate(0, 9, 0.5f, 0.0f)};
  state.candidates[0].plane.distance = 1.0f;
  state.candidates[1].plane.distance = 2.0f;
  ss::SymmetryFilterParams filter;
  filter.min_segment_points = 5;
  filter.plane_offset_search = 0.0f;  // the fake scores every moved plane 1: the third would pass

  state.stage_label = "filter";
  ss::FilterStage(filter).run(state);
  ASSERT_EQ(state.segments.size(), 2u) << "the third fails the occlusion threshold";

  state.stage_label = "nested";
  ss::NestedStage(ss::NestedSegmentParams{}, filter).run(state);
  ASSERT_EQ(state.segments.size(), 2u);
  EXPECT_EQ(state.segments[0].points.size(), 70u) << "the nested object is taken out of the large segment";

  state.stage_label = "dedup";
  ss::DuplicateStage(ss::DuplicateParams{}).run(state);
  EXPECT_EQ(state.segments.size(), 2u) << "what is left no longer overlaps";
  const ss::Counts expected = {{"filter.candidates", 3},
                               {"filter.kept", 2},
                               {"filter.kept_after_offset_fit", 0},
                               {"nested.trimmed", 1},
                               {"dedup.kept", 2}};
  EXPECT_EQ(state.counts, expected);
}

// ---- Regression: the default list gives the segments it gave ----------------------------------
//
// Fingerprint per segment (largest first): size, a hash of the input indices, the plane and the
// scores as exact floats. Refactoring the pipeline must not move any of them; a change meant to
// alter results rewrites test/data/default_list_segments.txt with SYMSEG_UPDATE_GOLDEN=1, and the
// diff shows in review.

namespace {

std::string fingerprint(const std::string& scene_name, const ss::SegmentationResult& result) {
  std::ostringstream out;
  out << scene_name << ": " << result.segments.size() << " segments\n";
  for (const ss::Segment& segment : result.segments) {
    std::uint64_t hash = 1469598103934665603ull;  // FNV-1a over the indices
    for (int i : segment.indices) {
      hash ^= static_cast<std::uint64_t>(i);
      hash *= 1099511628211ull;
    }
    char line[256];
    std::snprintf(line, sizeof(line), "  %zu %016llx %.9g %.9g %.9g %.9g %.9g %.9g\n", segment.indices.size(),
                  static_cast<unsigned long long>(hash), segment.symmetry->normal.x(), segment.symmetry->normal.y(),
                  segment.symmetry->normal.z(), segment.symmetry->distance, segment.scores->occlusion,
                  segment.scores->smoothness);
    out << line;
  }
  return out.str();
}

ss::Scene generated(ss::synthetic::SceneKind kind, int seed) {
  ss::synthetic::GeneratorOptions options;
  options.kind = kind;
  options.seed = seed;
  return ss::synthetic::generateScene(options);
}

}  // namespace

TEST(StagePipeline, TheDefaultListGivesTheSegmentsItGave) {
  ss::SegmentationConfig high_recall;
  high_recall.symmetry.filter.s_occl = 0.97f;
  high_recall.symmetry.filter.s_smooth = 0.05f;
  const auto balanced = ss::makeSegmenter("symmetry", ss::SegmentationConfig{});
  const auto recall = ss::makeSegmenter("symmetry", high_recall);
  std::string actual;
  const ss::Scene bundled = ss::loadScene(test_support::sourceDir() + "/data/default_scene");
  actual += fingerprint("default_scene (default)", balanced->segment(bundled));
  struct Generated {
    ss::synthetic::SceneKind kind;
    int seed;
    const char* name;
  };
  for (const Generated& g : {Generated{ss::synthetic::SceneKind::Stacked, 1, "stacked_1"},
                             Generated{ss::synthetic::SceneKind::Occluded, 1, "occluded_1"},
                             Generated{ss::synthetic::SceneKind::Touching, 2, "touching_2"}}) {
    actual += fingerprint(std::string(g.name) + " (high_recall)", recall->segment(generated(g.kind, g.seed)));
  }
  const std::string golden = test_support::sourceDir() + "/test/data/default_list_segments.txt";
  if (std::getenv("SYMSEG_UPDATE_GOLDEN")) test_support::writeTextFile(golden, actual);
  EXPECT_EQ(actual, test_support::readTextFile(golden))
      << "the default stage list gives other segments; if that is intended, rerun with SYMSEG_UPDATE_GOLDEN=1";
}
