// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "key_action_fixture.hpp"

namespace tutti::key_action {
namespace {

nlohmann::json valid_document() {
  return nlohmann::json::parse(R"({
    "white": {"front_y_mm": 0, "pivot_y_mm": 250, "front_dip_mm": 10},
    "black": {"front_y_mm": 50, "pivot_y_mm": 250, "front_dip_mm": 10},
    "escapement_fraction": 0.85, "damper_fraction": 0.5, "reset_fraction": 0.6,
    "return_s": 0.05,
    "velocity": {"silent_below_mm_s": 70, "min_mm_s": 100, "max_mm_s": 1200}})");
}

std::string error_of(const nlohmann::json& document) {
  auto action = key_action_from_json(document, "key_action.json");
  return action.ok() ? std::string("(loaded)") : action.error().message;
}

TEST(KeyActionParams, TheContentFileLoads) {
  auto action = load_key_action(key_action_path(test::content_dir()));
  ASSERT_TRUE(action.ok()) << action.error().message;
  EXPECT_DOUBLE_EQ(action->white.front_dip_mm, 10.0);
  EXPECT_GT(action->black.front_y_mm, action->white.front_y_mm);  // black keys are shorter
  EXPECT_LT(action->damper_fraction, action->escapement_fraction);
}

TEST(KeyActionParams, BadValuesNameTheFileAndPath) {
  auto doc = valid_document();
  doc["white"]["pivot_y_mm"] = 5;
  EXPECT_EQ(error_of(doc),
            "key_action.json: /white/pivot_y_mm: must lie at least 10 mm behind front_y_mm");
  doc = valid_document();
  doc["escapement_fraction"] = 1.5;
  EXPECT_NE(error_of(doc).find("key_action.json: /escapement_fraction: must lie in"),
            std::string::npos);
  doc = valid_document();
  doc["reset_fraction"] = 0.3;
  EXPECT_EQ(error_of(doc),
            "key_action.json: /reset_fraction: must lie in [damper_fraction, escapement_fraction)");
  doc = valid_document();
  doc["velocity"]["max_mm_s"] = 50;
  EXPECT_EQ(error_of(doc), "key_action.json: /velocity/max_mm_s: must exceed min_mm_s");
  doc = valid_document();
  doc["spare"] = 1;
  EXPECT_NE(error_of(doc).find("key_action.json"), std::string::npos);
  EXPECT_NE(error_of(doc).find("spare"), std::string::npos);
  doc = valid_document();
  doc.erase("black");
  EXPECT_EQ(error_of(doc), "key_action.json: /black: missing");
  EXPECT_EQ(error_of(valid_document()), "(loaded)");
}

// An instrument's own touch (content/piano/instruments.json) merged over the piano's: checked as a
// whole, errors naming the touch and the merged path; a fixed velocity ignores the key's speed.
TEST(KeyActionParams, AnInstrumentsTouchIsMergedOverThePianosAndChecked) {
  const auto path = key_action_path(test::content_dir());
  const nlohmann::json organ = {{"escapement_fraction", 0.3},
                                {"damper_fraction", 0.25},
                                {"reset_fraction", 0.25},
                                {"velocity", {{"silent_below_mm_s", 0}, {"fixed", 100}}}};
  auto action = load_key_action(path, organ, "instruments.json /instruments/organ/touch");
  ASSERT_TRUE(action.ok()) << action.error().message;
  EXPECT_DOUBLE_EQ(action->escapement_fraction, 0.3);
  EXPECT_DOUBLE_EQ(action->white.front_dip_mm, 10.0) << "what the touch leaves, stays the piano's";
  EXPECT_EQ(action->velocity.velocity_for(50.0), 100);
  EXPECT_EQ(action->velocity.velocity_for(1100.0), 100);
  auto piano = load_key_action(path, nlohmann::json::object(), "unused");
  ASSERT_TRUE(piano.ok());
  EXPECT_LT(piano->velocity.velocity_for(150.0), piano->velocity.velocity_for(1100.0));
  auto wrong = load_key_action(path, {{"damper_fraction", 0.9}},
                               "instruments.json /instruments/organ/touch");
  ASSERT_FALSE(wrong.ok());
  EXPECT_EQ(wrong.error().message,
            "instruments.json /instruments/organ/touch over key_action.json: /damper_fraction: must "
            "be below escapement_fraction");
  auto not_integer = load_key_action(path, {{"velocity", {{"fixed", 80.5}}}}, "t");
  ASSERT_FALSE(not_integer.ok());
  EXPECT_NE(not_integer.error().message.find("/velocity/fixed"), std::string::npos);
}

TEST(KeyActionParams, AMissingFileIsAnError) {
  auto action = load_key_action("/nonexistent/key_action.json");
  ASSERT_FALSE(action.ok());
  EXPECT_NE(action.error().message.find("/nonexistent/key_action.json"), std::string::npos);
}

TEST(KeyLever, TravelShrinksTowardThePivot) {
  const KeyLever white{0.0, 250.0, 10.0};
  EXPECT_DOUBLE_EQ(white.travel_at_mm(0.0), 10.0);
  EXPECT_DOUBLE_EQ(white.travel_at_mm(125.0), 5.0);
  EXPECT_DOUBLE_EQ(white.travel_at_mm(-30.0), 10.0);  // in front of the key: its front edge
  // At the contact point the key bed stops the key at its bed angle.
  EXPECT_NEAR(white.angle_rad(50.0, white.travel_at_mm(50.0)), white.bed_angle_rad(), 1e-12);
  EXPECT_DOUBLE_EQ(white.angle_rad(50.0, 30.0), white.bed_angle_rad());  // clamped to the bed
  EXPECT_DOUBLE_EQ(white.angle_rad(50.0, -2.0), 0.0);                    // above the key
  // The same depth pressed nearer the pivot turns the key further.
  EXPECT_GT(white.angle_rad(150.0, 3.0), white.angle_rad(20.0, 3.0));
}

TEST(VelocityCurve, SpeedAndVelocityInvertEachOther) {
  const VelocityCurve curve;
  EXPECT_EQ(curve.velocity_for(curve.min_mm_s), 1);
  EXPECT_EQ(curve.velocity_for(curve.max_mm_s), 127);
  EXPECT_EQ(curve.velocity_for(10.0 * curve.max_mm_s), 127);
  EXPECT_EQ(curve.velocity_for(0.5 * curve.min_mm_s), 1);
  for (int v = 1; v <= 127; ++v) EXPECT_EQ(curve.velocity_for(curve.speed_for(v)), v);
  EXPECT_LT(curve.speed_for(40), curve.speed_for(80));
}

}  // namespace
}  // namespace tutti::key_action
