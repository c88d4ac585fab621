// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>

#include <tutti/fingering_planner/cost_weights.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>

namespace tutti::fingering_planner {
namespace {

TEST(CostWeights, BothPresetsLoad) {
  auto paper = load_fingering_model("paper");
  ASSERT_TRUE(paper.ok()) << paper.error().message;
  EXPECT_TRUE(std::isinf(paper->weights.same_finger_other_key));
  EXPECT_DOUBLE_EQ(paper->weights.finger_use[0], 0.1);
  EXPECT_DOUBLE_EQ(paper->weights.black_key[0], 1.5);
  auto defaults = load_fingering_model("default");
  ASSERT_TRUE(defaults.ok()) << defaults.error().message;
  EXPECT_GT(defaults->weights.spacing_stretch, 0.0);
}

TEST(CostWeights, UnknownKeyIsAnErrorWithItsJsonPath) {
  const nlohmann::json doc = {{"crossing", {{"thumb", 1.0}, {"thumb_bogus", 2.0}}}};
  auto weights = cost_weights_from_json(doc, "default.json");
  ASSERT_FALSE(weights.ok());
  EXPECT_EQ(weights.error().message, "default.json: /crossing/thumb_bogus: unknown key");
  const nlohmann::json wrong = {{"fingers", {{"use", {1, 2, 3}}}}};
  auto bad = cost_weights_from_json(wrong, "x.json");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("x.json: /fingers/use: expected 5 numbers"),
            std::string::npos);
  auto missing = load_fingering_model("no_such_preset");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("no_such_preset.json"), std::string::npos);
}

TEST(CostWeights, OtherHandKeysLoadAndAreChecked) {
  auto empty = cost_weights_from_json(nlohmann::json::object(), "w.json");
  ASSERT_TRUE(empty.ok());
  EXPECT_EQ(empty->other_hand_per_white_key, 0.0);  // the paper plans one hand: off
  const nlohmann::json ok = {
      {"other_hand", {{"separation_white_keys", 5.0}, {"per_white_key", 2.0}, {"lead_s", 0.3}}}};
  auto weights = cost_weights_from_json(ok, "w.json");
  ASSERT_TRUE(weights.ok()) << weights.error().message;
  EXPECT_DOUBLE_EQ(weights->other_hand_separation, 5.0);
  EXPECT_DOUBLE_EQ(weights->other_hand_per_white_key, 2.0);
  EXPECT_DOUBLE_EQ(weights->other_hand_lead_s, 0.3);
  auto negative = cost_weights_from_json({{"other_hand", {{"per_white_key", -1.0}}}}, "w.json");
  ASSERT_FALSE(negative.ok());
  EXPECT_EQ(negative.error().message, "w.json: /other_hand/per_white_key: must be >= 0");
  auto defaults = load_fingering_model("default");
  ASSERT_TRUE(defaults.ok()) << defaults.error().message;
  EXPECT_GT(defaults->weights.other_hand_per_white_key, 0.0);
}

TEST(CostWeights, ShiftAndSpeedLimitKeysAreChecked) {
  const nlohmann::json ok = {{"hand_area",
                              {{"shift_time_s", 0.2},
                               {"shift_hold_fraction", 0.25},
                               {"speed_limit_white_keys_per_s", "inf"},
                               {"over_speed_per_white_key_per_s", 3.0}}},
                             {"fingers", {{"thumb_on_fourth", -0.1}}}};
  auto weights = cost_weights_from_json(ok, "w.json");
  ASSERT_TRUE(weights.ok()) << weights.error().message;
  EXPECT_DOUBLE_EQ(weights->shift_time_s, 0.2);
  EXPECT_DOUBLE_EQ(weights->shift_hold_fraction, 0.25);
  EXPECT_TRUE(std::isinf(weights->speed_limit));
  EXPECT_DOUBLE_EQ(weights->over_speed, 3.0);
  EXPECT_DOUBLE_EQ(weights->thumb_on_fourth, -0.1);
  // Absent keys keep the paper's values: no shift time, no limit.
  auto empty = cost_weights_from_json(nlohmann::json::object(), "w.json");
  ASSERT_TRUE(empty.ok());
  EXPECT_EQ(empty->shift_time_s, 0.0);
  EXPECT_TRUE(std::isinf(empty->speed_limit));
  EXPECT_EQ(empty->thumb_on_fourth, 0.0);
  for (const auto& [key, value, message] :
       {std::tuple{"shift_time_s", -0.1, "must be >= 0"},
        std::tuple{"shift_hold_fraction", 1.5, "must be within 0..1"},
        std::tuple{"speed_limit_white_keys_per_s", 0.0, "must be positive"},
        std::tuple{"over_speed_per_white_key_per_s", -1.0, "must be >= 0"}}) {
    const nlohmann::json bad = {{"hand_area", {{key, value}}}};
    auto result = cost_weights_from_json(bad, "w.json");
    ASSERT_FALSE(result.ok()) << key;
    EXPECT_EQ(result.error().message, std::string("w.json: /hand_area/") + key + ": " + message);
  }
  auto defaults = load_fingering_model("default");
  ASSERT_TRUE(defaults.ok());
  EXPECT_TRUE(std::isfinite(defaults->weights.speed_limit));
  EXPECT_GT(defaults->weights.over_speed, 0.0);
}

}  // namespace
}  // namespace tutti::fingering_planner
