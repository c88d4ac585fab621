// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <tutti/finger_motion/finger_motion_params.hpp>
#include "finger_motion_fixture.hpp"
#include <tutti/piano_model/json_document.hpp>

namespace tutti::finger_motion {
namespace {

nlohmann::json content_json() {
  auto document = piano_model::read_json_file(finger_motion_params_path(test::content_dir()));
  EXPECT_TRUE(document.ok());
  return *document;
}

TEST(FingerMotionParams, ContentFileLoads) {
  const FingerMotionParams& p = test::models().params;
  EXPECT_GT(p.keys.black_top_z_mm, p.keys.white_top_z_mm);
  EXPECT_NEAR(p.keys.dip_mm, 10.0, 2.0);
  for (const FingerGeometry& g : p.fingers) {
    EXPECT_GT(g.phalanges_mm[0], g.phalanges_mm[2]);
    EXPECT_NE(g.white_bend_rad, g.black_bend_rad);
  }
}

TEST(FingerMotionParams, UnknownKeyIsNamed) {
  nlohmann::json doc = content_json();
  doc["timing"]["press_led_s"] = 0.1;
  auto p = finger_motion_params_from_json(doc, "finger_motion.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message,
            "finger_motion.json: /timing/press_led_s: unknown key (did you mean "
            "\"press_lead_s\"?)");
}

TEST(FingerMotionParams, BadValuesAreNamed) {
  nlohmann::json doc = content_json();
  doc["fingers"]["3"]["phalanges_mm"][1] = -2;
  auto p = finger_motion_params_from_json(doc, "f.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message, "f.json: /fingers/3/phalanges_mm/1: expected a positive number");

  doc = content_json();
  doc["keys"].erase("dip_mm");
  p = finger_motion_params_from_json(doc, "f.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message, "f.json: /keys/dip_mm: missing");

  doc = content_json();
  doc["fingers"]["1"]["pad_drop_mm"] = 40;
  p = finger_motion_params_from_json(doc, "f.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message, "f.json: /fingers/1/pad_drop_mm: expected 0..15 mm");

  doc = content_json();
  doc["timing"]["move_max_s"] = 0.01;
  p = finger_motion_params_from_json(doc, "f.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message, "f.json: /timing/move_max_s: below move_min_s");
}

// The keys' lever and the hand's move in (optional: older files have none): bad values are named.
TEST(FingerMotionParams, BadLeverAndReachInValuesAreNamed) {
  nlohmann::json doc = content_json();
  doc["keys"]["pivot_y_mm"] = 40.0;  // in front of where black keys are pressed
  auto p = finger_motion_params_from_json(doc, "f.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message, "f.json: /keys/pivot_y_mm: must lie behind where black keys are pressed");

  doc = content_json();
  doc["keys"]["black_press_in_mm"] = "deep";
  p = finger_motion_params_from_json(doc, "f.json");
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().message.find("f.json: /keys/black_press_in_mm: "), std::string::npos)
      << p.error().message;

  doc = content_json();
  doc["timing"]["reach_in_s"] = 0.0;  // an ease takes time
  p = finger_motion_params_from_json(doc, "f.json");
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().message.find("f.json: /timing/reach_in_s: "), std::string::npos)
      << p.error().message;

  doc = content_json();
  doc["keys"].erase("pivot_y_mm");  // no lever: every key travels the whole dip
  doc["timing"].erase("reach_in_s");
  p = finger_motion_params_from_json(doc, "f.json");
  ASSERT_TRUE(p.ok()) << p.error().message;
  EXPECT_EQ(p->keys.pivot_y_mm, 0.0);
}

TEST(FingerMotionParams, PassOverIsOptionalAndChecked) {
  nlohmann::json doc = content_json();
  ASSERT_TRUE(doc.contains("pass_over"));
  auto p = finger_motion_params_from_json(doc, "f.json");
  ASSERT_TRUE(p.ok()) << p.error().message;
  EXPECT_EQ(p->pass_over.lift_mm, doc["pass_over"]["lift_mm"].get<double>());

  doc["pass_over"]["gap_mm"] = -5.0;
  p = finger_motion_params_from_json(doc, "f.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().message, "f.json: /pass_over/gap_mm: must be positive");

  doc = content_json();
  doc["pass_over"]["lift"] = 30.0;
  p = finger_motion_params_from_json(doc, "f.json");
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().message.find("f.json: /pass_over/lift: unknown key"), std::string::npos)
      << p.error().message;

  doc = content_json();
  doc["pass_over"]["lift_mm"] = 0.0;  // allowed: no hand is lifted
  p = finger_motion_params_from_json(doc, "f.json");
  ASSERT_TRUE(p.ok()) << p.error().message;

  doc = content_json();
  doc.erase("pass_over");
  p = finger_motion_params_from_json(doc, "f.json");
  ASSERT_TRUE(p.ok()) << p.error().message;
  EXPECT_EQ(p->pass_over.lift_mm, PassOverParams{}.lift_mm);
}

TEST(FingerMotionParams, MissingFileIsAnError) {
  auto p = load_finger_motion_params("/nonexistent/finger_motion.json");
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().message.find("finger_motion.json"), std::string::npos);
}

}  // namespace
}  // namespace tutti::finger_motion
