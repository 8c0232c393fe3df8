#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <set>
#include <yaml-cpp/yaml.h>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/parameter_schema.h"
#include "symmetry_segmentation/segmentation_config.h"
#include "symmetry_segmentation/segments_json.h"
#include "test_support.h"

namespace ss = symmetry_segmentation;

TEST(Config, DefaultFileMatchesBuiltInDefaults) {
  const auto from_file = ss::loadConfigFile(test_support::sourceDir() + "/config/default.yaml");
  const ss::SegmentationConfig built_in;
  EXPECT_EQ(from_file.preprocessing.voxel_size, built_in.preprocessing.voxel_size);
  EXPECT_EQ(from_file.lccp.concavity_tolerance, built_in.lccp.concavity_tolerance);
  EXPECT_EQ(from_file.lccp.seed_resolution, built_in.lccp.seed_resolution);
  EXPECT_EQ(from_file.euclidean.cluster_tolerance, built_in.euclidean.cluster_tolerance);
  EXPECT_EQ(from_file.euclidean.min_cluster_size, built_in.euclidean.min_cluster_size);
  EXPECT_EQ(from_file.symmetry.cut.dmax, built_in.symmetry.cut.dmax);
  EXPECT_EQ(from_file.symmetry.cut.sigma_concave_deg, built_in.symmetry.cut.sigma_concave_deg);
  EXPECT_EQ(from_file.symmetry.curve_pairs.max_tangent_angle_deg, built_in.symmetry.curve_pairs.max_tangent_angle_deg);
  EXPECT_EQ(from_file.symmetry.filter.s_occl, built_in.symmetry.filter.s_occl);
  EXPECT_EQ(from_file.symmetry.refine.icp_iterations, built_in.symmetry.refine.icp_iterations);
}

TEST(Config, PresetsSetTheFilterThresholds) {
  const auto high_recall = ss::loadConfigFile(test_support::sourceDir() + "/config/high_recall.yaml");
  EXPECT_FLOAT_EQ(high_recall.symmetry.filter.s_occl, 0.97f);
  EXPECT_FLOAT_EQ(high_recall.symmetry.filter.s_smooth, 0.05f);
  const auto balanced = ss::loadConfigFile(test_support::sourceDir() + "/config/balanced.yaml");
  EXPECT_FLOAT_EQ(balanced.symmetry.filter.s_occl, 0.99f);
  EXPECT_FLOAT_EQ(balanced.symmetry.filter.s_smooth, 0.02f);
  // The authors' method alone: the paper's stages with rotational symmetry (upright axes, no
  // face planes), none of the additions, and a list that runs.
  const auto paper = ss::loadConfigFile(test_support::sourceDir() + "/config/paper.yaml");
  EXPECT_EQ(paper.symmetry.stages, (std::vector<std::string>{"curves", "curve_pairs", "upright", "cut", "refine",
                                                             "filter", "dedup", "object_bottoms"}));
  EXPECT_EQ(paper.symmetry.upright.flat_curvature, 0.0f);
  EXPECT_EQ(paper.symmetry.cut.unobserved_steps, 2);
  EXPECT_EQ(paper.symmetry.filter.plane_offset_search, 0.0f);
  EXPECT_TRUE(ss::stageListProblems(paper.symmetry.stages).empty());
  ss::SegmentationConfig config;
  ss::setConfigValue(config, "symmetry.filter.s_occl", "0.5");
  EXPECT_FLOAT_EQ(config.symmetry.filter.s_occl, 0.5f);
  EXPECT_THROW(ss::setConfigValue(config, "symmetry.cut.dbuf", "0.001"), ss::InputError);  // below dmax
  EXPECT_THROW(ss::configFromYaml(YAML::Load("symmetry: {filter: {s_ocl: 1}}")), ss::InputError);
}

TEST(Config, OverridesAndRejectsTypos) {
  auto config = ss::configFromYaml(YAML::Load("lccp: {concavity_tolerance: 25}\neuclidean: {min_cluster_size: 7}"));
  EXPECT_EQ(config.lccp.concavity_tolerance, 25.0f);
  EXPECT_EQ(config.euclidean.min_cluster_size, 7);
  ss::setConfigValue(config, "preprocessing.voxel_size", "0.02");
  EXPECT_FLOAT_EQ(config.preprocessing.voxel_size, 0.02f);
  EXPECT_THROW(ss::configFromYaml(YAML::Load("lccp: {concavity: 25}")), ss::InputError);
  EXPECT_THROW(ss::configFromYaml(YAML::Load("lccp: {concavity_tolerance: abc}")), ss::InputError);
  EXPECT_THROW(ss::configFromYaml(YAML::Load("[1, 2]")), ss::InputError);
  EXPECT_THROW(ss::setConfigValue(config, "preprocessing.voxel_size", "-1"), ss::InputError);
  EXPECT_THROW(ss::setConfigValue(config, "nosection", "1"), ss::InputError);
  EXPECT_THROW(ss::loadConfigFile("/nonexistent/config.yaml"), ss::InputError);
}

TEST(ParameterSchema, GeneratedFilesAreCurrent) {
  // config/default.yaml and cfg/live_parameters.yaml are written from the schema
  // (segment_scene --print-config / --print-live-parameters): a stale copy misdocuments.
  EXPECT_EQ(test_support::readTextFile(test_support::sourceDir() + "/config/default.yaml"), ss::documentedDefaultConfig())
      << "regenerate: segment_scene --print-config > config/default.yaml";
  EXPECT_EQ(test_support::readTextFile(test_support::sourceDir() + "/cfg/live_parameters.yaml"), ss::liveParametersYaml())
      << "regenerate: segment_scene --print-live-parameters > cfg/live_parameters.yaml";
}

TEST(ParameterSchema, EveryParameterIsDocumentedOnceWithItsDefaultInRange) {
  const ss::SegmentationConfig defaults;
  std::set<std::string> keys;
  for (const ss::ParameterInfo& info : ss::parameterSchema()) {
    EXPECT_TRUE(keys.insert(info.key).second) << info.key << " declared twice";
    EXPECT_FALSE(info.doc.empty()) << info.key;
    EXPECT_EQ(ss::configValueText(defaults, info.key), info.default_value) << info.key;
    if (info.type == "float" || info.type == "int") {
      EXPECT_LT(info.min, info.max) << info.key;
    }
  }
  EXPECT_TRUE(ss::configProblems(defaults).empty());
  EXPECT_NE(ss::findParameter("symmetry.filter.s_occl"), nullptr);
  EXPECT_TRUE(ss::findParameter("symmetry.filter.s_occl")->live);
  EXPECT_EQ(ss::findParameter("symmetry.filter.no_such_key"), nullptr);
}

TEST(ParameterSchema, ValuesAreValidatedTogetherInAnyOrder) {
  // Checked one by one, lowering both alpha bounds failed in one order and passed in the other.
  const ss::SegmentationConfig defaults;
  const auto a = ss::configWithValues(defaults, {{"symmetry.cut.alpha_max_deg", "10"}, {"symmetry.cut.alpha_min_deg", "5"}});
  const auto b = ss::configWithValues(defaults, {{"symmetry.cut.alpha_min_deg", "5"}, {"symmetry.cut.alpha_max_deg", "10"}});
  EXPECT_FLOAT_EQ(a.symmetry.cut.alpha_min_deg, 5.0f);
  EXPECT_FLOAT_EQ(a.symmetry.cut.alpha_max_deg, 10.0f);
  EXPECT_FLOAT_EQ(b.symmetry.cut.alpha_min_deg, 5.0f);
  EXPECT_FLOAT_EQ(b.symmetry.cut.alpha_max_deg, 10.0f);
  EXPECT_THROW(ss::configWithValues(defaults, {{"symmetry.cut.alpha_max_deg", "10"}}), ss::InputError);
}

TEST(ParameterSchema, ARejectedConfigurationLeavesThePreviousOneInForce) {
  // setConfigValue used to write the value before validating and never roll back: a rejected
  // s_occl of 1.5 was logged as ignored yet used.
  ss::SegmentationConfig config;
  EXPECT_THROW(ss::setConfigValue(config, "symmetry.filter.s_occl", "1.5"), ss::InputError);
  EXPECT_FLOAT_EQ(config.symmetry.filter.s_occl, 0.99f);
  const ss::SegmentationConfig base = config;
  try {
    ss::configWithValues(base, {{"symmetry.filter.s_smooth", "0.05"}, {"symmetry.filter.s_occl", "1.5"},
                                {"symmetry.filter.no_such_key", "1"}, {"lccp.min_points", "many"}});
    ADD_FAILURE() << "accepted";
  } catch (const ss::InputError& error) {
    const std::string message = error.what();
    for (const char* named : {"symmetry.filter.s_occl", "no_such_key", "lccp.min_points"}) {
      EXPECT_NE(message.find(named), std::string::npos) << message;
    }
    EXPECT_EQ(message.find("s_smooth"), std::string::npos) << "a good value is no problem: " << message;
  }
  EXPECT_FLOAT_EQ(base.symmetry.filter.s_smooth, 0.02f);
}

TEST(SegmentsJson, RoundTripKeepsEverything) {
  ss::SegmentationResult result;
  result.input_points = 10;
  ss::Segment plain;
  plain.indices = {0, 3, 9};
  ss::Segment with_plane;
  with_plane.indices = {1, 2};
  with_plane.symmetry = ss::SymmetryPlane{Eigen::Vector3f(0, 1, 0), -0.12f};
  with_plane.scores = ss::SegmentScores{0.98f, 0.01f};
  ss::ObjectBox box;
  box.center = Eigen::Vector3f(0.1f, 0.2f, 0.75f);
  box.axes = Eigen::AngleAxisf(0.5f, Eigen::Vector3f::UnitZ()).toRotationMatrix();
  box.size = Eigen::Vector3f(0.2f, 0.1f, 0.05f);
  with_plane.box = box;
  result.segments = {plain, with_plane};
  result.timing_ms = {{"preprocess", 12.5}, {"total", 40.0}};
  result.support = ss::SupportSurface{Eigen::Vector4f(0, 0, 1, -0.7f),
                                      {{0.f, 0.f, 0.7f}, {1.f, 0.f, 0.7f}, {0.5f, 1.f, 0.7f}}, 0.0025f};
  const std::string dir = test_support::makeTempDir("segments_json");
  ss::writeSegmentsJson(result, dir + "/s.json");
  const auto loaded = ss::readSegmentsJson(dir + "/s.json");
  EXPECT_EQ(loaded.input_points, 10u);
  ASSERT_EQ(loaded.segments.size(), 2u);
  EXPECT_EQ(loaded.segments[0].indices, plain.indices);
  EXPECT_FALSE(loaded.segments[0].symmetry.has_value());
  ASSERT_TRUE(loaded.segments[1].symmetry.has_value());
  EXPECT_FLOAT_EQ(loaded.segments[1].symmetry->distance, -0.12f);
  EXPECT_FLOAT_EQ(loaded.segments[1].scores->occlusion, 0.98f);
  EXPECT_FALSE(loaded.segments[0].box.has_value());
  ASSERT_TRUE(loaded.segments[1].box.has_value());
  EXPECT_TRUE(loaded.segments[1].box->center.isApprox(box.center));
  EXPECT_TRUE(loaded.segments[1].box->axes.isApprox(box.axes));  // columns written as rows, read back as columns
  EXPECT_TRUE(loaded.segments[1].box->size.isApprox(box.size));
  ASSERT_EQ(loaded.timing_ms.size(), 2u);
  EXPECT_EQ(loaded.timing_ms[1].first, "total");
  ASSERT_TRUE(loaded.support.has_value());
  EXPECT_FLOAT_EQ(loaded.support->plane[3], -0.7f);
  ASSERT_EQ(loaded.support->polygon.size(), 3u);
  EXPECT_FLOAT_EQ(loaded.support->polygon[2].y(), 1.0f);
  EXPECT_FLOAT_EQ(loaded.support->noise, 0.0025f);
  // Files written before the support carried the sensor's noise read as noise 0.
  test_support::writeTextFile(dir + "/old.json",
                              "{\"input_points\": 3, \"support\": {\"plane\": [0, 0, 1, 0], \"polygon\": []}, \"segments\": []}");
  const auto old = ss::readSegmentsJson(dir + "/old.json");
  ASSERT_TRUE(old.support.has_value());
  EXPECT_EQ(old.support->noise, 0.0f);
}

TEST(SegmentsJson, MalformedFilesAreErrors) {
  const std::string dir = test_support::makeTempDir("segments_json_bad");
  for (const char* bad : {"{", "{\"segments\": []}", "{\"input_points\": 3, \"segments\": [{\"indices\": [5]}]}",
                          "{\"input_points\": 3, \"segments\": [{\"indices\": \"x\"}]}",
                          "{\"input_points\": 3, \"support\": {\"plane\": [0, 0, 1]}, \"segments\": []}",
                          "{\"input_points\": 3, \"support\": {\"plane\": [0, 0, 0, 1], \"polygon\": []}, \"segments\": []}",
                          "{\"input_points\": 3, \"support\": {\"plane\": [0, 0, 1, 0], \"polygon\": [[1, 2]]}, \"segments\": []}",
                          "{\"input_points\": 3, \"support\": {\"plane\": [0, 0, 1, 0], \"polygon\": [], \"noise\": -1}, \"segments\": []}",
                          "{\"input_points\": 3, \"support\": {\"plane\": [0, 0, 1, 0], \"polygon\": [], \"noise\": \"x\"}, \"segments\": []}"}) {
    test_support::writeTextFile(dir + "/bad.json", bad);
    EXPECT_THROW(ss::readSegmentsJson(dir + "/bad.json"), ss::InputError) << bad;
  }
  EXPECT_THROW(ss::readSegmentsJson(dir + "/missing.json"), ss::InputError);
}
