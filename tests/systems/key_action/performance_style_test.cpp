// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "key_action_fixture.hpp"

namespace tutti::key_action {
namespace {

TEST(PerformanceStyle, TheContentHasThePreciseGentleAndBeginnerStyles) {
  const StyleBook& book = test::content().styles;
  ASSERT_EQ(book.styles.size(), 3u);
  const PerformanceStyle precise = test::style("precise");
  const PerformanceStyle gentle = test::style("gentle");
  const PerformanceStyle beginner = test::style("beginner");
  // What the names promise, as data: gentle is softer and slower, the beginner flatter and
  // slower with weak outer fingers.
  EXPECT_LT(gentle.strength, precise.strength);
  EXPECT_GT(gentle.min_stroke_s, precise.min_stroke_s);
  EXPECT_LT(beginner.bend_scale, precise.bend_scale);
  EXPECT_LT(beginner.hover_lift_mm, precise.hover_lift_mm);
  EXPECT_LT(beginner.finger_speed[4], beginner.finger_speed[1]);
  EXPECT_EQ(precise.timing_spread_ms, 0.0);
}

TEST(PerformanceStyle, AnUnknownStyleListsTheKnownOnes) {
  auto found = test::content().styles.find("virtuoso");
  ASSERT_FALSE(found.ok());
  EXPECT_EQ(found.error().message,
            "unknown performance style 'virtuoso' (styles: beginner, gentle, precise)");
}

TEST(PerformanceStyle, BadValuesNameTheFileAndPath) {
  auto document = nlohmann::json::parse(R"({"styles": {"x": {
      "strength": 1, "min_stroke_s": 0.02, "max_stroke_s": 0.2, "hover_lift_mm": 9,
      "bend_scale": 1, "finger_speed": [1, 1, 1, 1, 1], "timing_spread_ms": 0,
      "strength_spread": 0, "release_anticipation": 1, "release_s": 0.04,
      "relax_time_constant_s": 0.15}}})");
  ASSERT_TRUE(styles_from_json(document, "styles.json").ok());
  auto bad = document;
  bad["styles"]["x"]["finger_speed"] = {1, 1, 1};
  EXPECT_EQ(styles_from_json(bad, "styles.json").error().message,
            "styles.json: /styles/x/finger_speed: expected 5 numbers (thumb .. little finger)");
  bad = document;
  bad["styles"]["x"]["max_stroke_s"] = 0.01;
  EXPECT_EQ(styles_from_json(bad, "styles.json").error().message,
            "styles.json: /styles/x/max_stroke_s: must not be below min_stroke_s");
  bad = document;
  bad["styles"]["x"].erase("strength");
  EXPECT_NE(styles_from_json(bad, "styles.json").error().message.find("/styles/x"),
            std::string::npos);
  bad = document;
  bad["styles"]["x"]["typo"] = 1;
  EXPECT_NE(styles_from_json(bad, "styles.json").error().message.find("typo"), std::string::npos);
  EXPECT_FALSE(styles_from_json(nlohmann::json::parse(R"({"styles": {}})"), "styles.json").ok());
}

TEST(PerformanceStyle, ApplyingAStyleChangesTheFingersItNames) {
  const finger_motion::FingerMotionParams& base = test::content().params;
  const PerformanceStyle beginner = test::style("beginner");
  const finger_motion::FingerMotionParams styled = apply_style(base, beginner);
  EXPECT_EQ(styled.keys.hover_lift_mm, beginner.hover_lift_mm);
  EXPECT_EQ(styled.timing.release_s, beginner.release_s);
  for (std::size_t f = 0; f < 5; ++f) {
    EXPECT_DOUBLE_EQ(styled.fingers[f].white_bend_rad,
                     base.fingers[f].white_bend_rad * beginner.bend_scale);
    EXPECT_EQ(styled.fingers[f].neutral_bend_rad, base.fingers[f].neutral_bend_rad);
    EXPECT_EQ(styled.fingers[f].phalanges_mm, base.fingers[f].phalanges_mm);
  }
}

}  // namespace
}  // namespace tutti::key_action
