// The dynamic_reconfigure types generated from cfg/live_parameters.yaml against the parameter
// schema, and the conversions between their values and the core's dotted keys. No roscore.
#include <gtest/gtest.h>

#include <set>

#include <yaml-cpp/yaml.h>

#include "symmetry_segmentation/LiveSymmetryFilterConfig.h"
#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/parameter_schema.h"
#include "symmetry_segmentation/ros/live_parameters.h"
#include "symmetry_segmentation/ros/live_sections.h"

namespace ss = symmetry_segmentation;

TEST(LiveParameters, EveryLiveParameterOfTheSchemaHasExactlyOneServer) {
  for (const auto& problem : ss::liveSectionProblems()) ADD_FAILURE() << problem;
  std::set<std::string> served;
  for (const auto& type : ss::liveSectionTypes()) {
    for (const auto& key : type.keys()) {
      EXPECT_TRUE(served.insert(key).second) << key << " served twice";
      EXPECT_EQ(key.rfind(type.section + ".", 0), 0u) << key << " outside its section " << type.section;
    }
  }
  std::size_t live = 0;
  for (const auto& info : ss::parameterSchema()) live += info.live ? 1 : 0;
  EXPECT_EQ(served.size(), live);
  EXPECT_GE(live, 5u);
}

TEST(LiveParameters, GeneratedDefaultsAndRangesAreTheSchemas) {
  // What rqt_reconfigure offers (and dynamic_reconfigure clamps to) is the schema's range.
  const std::string section = "symmetry.filter";
  using Config = ss::LiveSymmetryFilterConfig;
  const auto defaults = ss::liveValues(section, Config::__getDefault__());
  const auto minima = ss::liveValues(section, Config::__getMin__());
  const auto maxima = ss::liveValues(section, Config::__getMax__());
  ASSERT_FALSE(defaults.empty());
  for (std::size_t i = 0; i < defaults.size(); ++i) {
    const ss::ParameterInfo* info = ss::findParameter(defaults[i].first);
    ASSERT_NE(info, nullptr) << defaults[i].first;
    EXPECT_FLOAT_EQ(YAML::Load(defaults[i].second).as<float>(), YAML::Load(info->default_value).as<float>()) << info->key;
    EXPECT_DOUBLE_EQ(YAML::Load(minima[i].second).as<double>(), info->min) << info->key;
    EXPECT_DOUBLE_EQ(YAML::Load(maxima[i].second).as<double>(), info->max) << info->key;
  }
}

TEST(LiveParameters, ValuesRoundTripThroughTheGeneratedType) {
  ss::SegmentationConfig config;
  config.symmetry.filter.s_occl = 0.97f;
  config.symmetry.filter.s_smooth = 0.05f;
  const std::string section = "symmetry.filter";
  ss::ConfigValues in_force;
  for (const auto& key : ss::liveKeys<ss::LiveSymmetryFilterConfig>(section)) {
    in_force.emplace_back(key, ss::configValueText(config, key));
  }
  ss::LiveSymmetryFilterConfig live;
  ss::setLiveValues(section, in_force, live);
  EXPECT_DOUBLE_EQ(live.s_occl, 0.97);  // the text of the float, 0.97, not 0.9700000286
  // Back to the core: the same configuration.
  const auto applied = ss::configWithValues(ss::SegmentationConfig(), ss::liveValues(section, live));
  EXPECT_EQ(applied.symmetry.filter.s_occl, 0.97f);
  EXPECT_EQ(applied.symmetry.filter.s_smooth, 0.05f);
  // A value missing or of the wrong type is an error, not a silent default.
  in_force.pop_back();
  EXPECT_THROW(ss::setLiveValues(section, in_force, live), ss::InputError);
  EXPECT_THROW(ss::setLiveValues(section, {{"symmetry.filter.s_occl", "high"}, {"symmetry.filter.s_smooth", "0.1"}}, live),
               ss::InputError);
}

TEST(LiveParameters, ParameterPathsAreTheNestedNames) {
  EXPECT_EQ(ss::parameterPath("symmetry.filter"), "symmetry/filter");
  EXPECT_EQ(ss::parameterPath("symmetry.filter.s_occl"), "symmetry/filter/s_occl");
}
