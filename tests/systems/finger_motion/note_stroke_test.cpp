// SPDX-License-Identifier: MIT
// Strokes decided by a performance style (NoteStroke): the contact reaches the key bed at the
// stroke's bottom time, from its start, to its travel; without strokes nothing changes.
#include <gtest/gtest.h>

#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include "finger_motion_fixture.hpp"

namespace tutti::finger_motion {
namespace {

TEST(NoteStroke, TheContactFollowsTheStroke) {
  const test::TestScore s = test::make_score({{64, 1.0, 1.5, 3}, {65, 2.0, 2.4, 4}});
  const Models& m = test::models();
  const std::vector<NoteStroke> strokes = {{0.93, 1.01, 1.45, 8.0}, {1.85, 2.02, 2.3, 7.5}};
  auto plan = plan_finger_motion(s.score, s.plan, test::constant_path(600.0),
                                 test::constant_path(300.0), m.keyboard, m.hand, m.params, strokes);
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  const KeyContact& c = plan->right.fingers[2].front();
  EXPECT_DOUBLE_EQ(c.onset_s, 1.01);
  EXPECT_DOUBLE_EQ(c.stroke_start_s, 0.93);
  EXPECT_DOUBLE_EQ(c.offset_s, 1.45);
  // A stroke's travel is the key's where the pad lands (key_action's contact point): with the
  // hand at its rest line over a white key, the bed is that far below the key's top.
  EXPECT_NEAR(c.bottom_z_mm, m.params.keys.white_top_z_mm - 8.0, 1e-9);
  // The tip reaches that bed at the bottom time, pressing fully, and is above it before.
  FingerPose pose;
  evaluate_finger_pose(*plan, components::HandSide::right, 3, 600.0, 1.01, pose);
  EXPECT_NEAR(pose.contact_z_mm, c.bottom_z_mm, 1e-9);
  EXPECT_DOUBLE_EQ(pose.press_depth, 1.0);
  evaluate_finger_pose(*plan, components::HandSide::right, 3, 600.0, 0.99, pose);
  EXPECT_GT(pose.contact_z_mm, c.bottom_z_mm + 0.5);
  EXPECT_GT(pose.press_depth, 0.0);
  EXPECT_LT(pose.press_depth, 1.0);
}

TEST(NoteStroke, WithoutStrokesTheKeyboardDipIsTheTravel) {
  FingerMotionParams no_rail = test::models().params;
  no_rail.keys.pivot_y_mm = 0.0;  // the lever's travel along the key is KeyStroke's test
  const FingerMotionPlan plan = test::plan_notes({{64, 1.0, 1.5, 3}}, 600.0, 300.0, no_rail);
  const KeyContact& c = plan.right.fingers[2].front();
  EXPECT_DOUBLE_EQ(c.bottom_z_mm,
                   test::models().params.keys.white_top_z_mm - test::models().params.keys.dip_mm);
  EXPECT_DOUBLE_EQ(c.onset_s, 1.0);
  EXPECT_DOUBLE_EQ(c.stroke_start_s, 1.0 - test::models().params.timing.press_lead_s);
}

TEST(NoteStroke, BadStrokesAreErrorsNamingTheNote) {
  const test::TestScore s = test::make_score({{64, 1.0, 1.5, 3}, {65, 2.0, 2.4, 4}});
  const Models& m = test::models();
  const auto plan_with = [&](const std::vector<NoteStroke>& strokes) {
    return plan_finger_motion(s.score, s.plan, test::constant_path(600.0),
                              test::constant_path(300.0), m.keyboard, m.hand, m.params, strokes);
  };
  auto short_list = plan_with({{0.9, 1.0, 1.5, 8.0}});
  ASSERT_FALSE(short_list.ok());
  EXPECT_EQ(short_list.error().message, "score: 1 note strokes for 2 notes");
  auto backwards = plan_with({{0.9, 1.0, 1.5, 8.0}, {2.1, 2.0, 2.4, 8.0}});
  ASSERT_FALSE(backwards.ok());
  EXPECT_EQ(backwards.error().message,
            "score: note 1: invalid stroke (start before bottom, travel > 0)");
  auto no_travel = plan_with({{0.9, 1.0, 1.5, 0.0}, {1.9, 2.0, 2.4, 8.0}});
  ASSERT_FALSE(no_travel.ok());
  EXPECT_NE(no_travel.error().message.find("note 0"), std::string::npos);
}

}  // namespace
}  // namespace tutti::finger_motion
