// SPDX-License-Identifier: MIT
// Key stroke: joint 1 strikes (MCP; thumb: abduction), joints 2-3 shaped before and fixed during
// the stroke, press depth 1 exactly at the onset, held to the offset, released after.
#include <gtest/gtest.h>

#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include "finger_motion_fixture.hpp"

namespace tutti::finger_motion {
namespace {

using components::HandSide;

FingerPose pose_at(const FingerMotionPlan& plan, int finger, double hand_x, double t) {
  FingerPose pose;
  evaluate_finger_pose(plan, HandSide::right, finger, hand_x, t, pose);
  return pose;
}

TEST(KeyStroke, PressDepthReachesOneAtOnsetAndIsHeld) {
  const Models& m = test::models();
  const double x = m.keyboard.x_mm(60);
  const FingerMotionPlan plan = test::plan_notes({{60, 1.0, 1.5, 3}}, x, 0);
  const double lead = m.params.timing.press_lead_s;
  EXPECT_EQ(pose_at(plan, 3, x, 1.0 - lead - 1e-6).press_depth, 0.0);
  EXPECT_LT(pose_at(plan, 3, x, 1.0 - 1e-3).press_depth, 1.0);
  const FingerPose at_onset = pose_at(plan, 3, x, 1.0);
  EXPECT_EQ(at_onset.press_depth, 1.0);
  EXPECT_EQ(at_onset.key, 60);
  // On the bed of the key where the pad lands: the lever's travel there, never below the dip
  // at the front edge.
  const KeyContact& contact = plan.right.fingers[2].front();
  EXPECT_EQ(at_onset.contact_z_mm, contact.bottom_z_mm);
  EXPECT_LT(contact.bottom_z_mm, m.params.keys.white_top_z_mm - 0.5 * m.params.keys.dip_mm);
  EXPECT_GE(contact.bottom_z_mm, m.params.keys.white_top_z_mm - m.params.keys.dip_mm);
  EXPECT_EQ(pose_at(plan, 3, x, 1.25).press_depth, 1.0);
  EXPECT_EQ(pose_at(plan, 3, x, 1.5).press_depth, 1.0);
  const double mid_release = pose_at(plan, 3, x, 1.5 + 0.2 * m.params.timing.release_s).press_depth;
  EXPECT_GT(mid_release, 0.0);
  EXPECT_LT(mid_release, 1.0);
  const FingerPose after = pose_at(plan, 3, x, 1.5 + m.params.timing.release_s + 1e-6);
  EXPECT_EQ(after.press_depth, 0.0);
  EXPECT_EQ(after.key, -1);
}

// A finger that leaves a black key for a white one lowers toward the white key's hover height,
// below the black key's top, beside it: the black key stays up once it is let go (the third-party
// pieces showed keys half down a second after their note).
TEST(KeyStroke, AFingerLeavingABlackKeyForAWhiteOneLeavesItUp) {
  const Models& m = test::models();
  const double x = m.keyboard.x_mm(62);
  const FingerMotionPlan plan = test::plan_notes({{61, 0.5, 1.0, 3}, {64, 2.0, 2.5, 3}}, x, 0);
  const KeyContact& black = plan.right.fingers[2].front();
  ASSERT_TRUE(black.black);
  const KeyContact& white = plan.right.fingers[2].back();
  ASSERT_LT(black.release_end_s, white.shape_start_s);
  for (double t = black.release_end_s; t < white.stroke_start_s; t += 0.005) {
    const FingerPose pose = pose_at(plan, 3, x, t);
    EXPECT_EQ(pose.press_depth, 0.0) << "at " << t << " s";
    EXPECT_EQ(pose.key, -1) << "at " << t << " s";
  }
}

TEST(KeyStroke, FingersStrikeWithMcpAndKeepPipDipFixed) {
  const Models& m = test::models();
  const double lead = m.params.timing.press_lead_s;
  for (int finger = 2; finger <= 5; ++finger) {
    const FingerMotionPlan plan = test::plan_notes({{60, 1.0, 1.5, finger}}, 600, 0);
    const FingerPose start = pose_at(plan, finger, 600, 1.0 - lead);
    double previous_mcp = start.mcp_flexion_rad;
    for (int i = 1; i <= 20; ++i) {
      const FingerPose p = pose_at(plan, finger, 600, 1.0 - lead + lead * i / 20.0);
      EXPECT_GT(p.mcp_flexion_rad, previous_mcp) << "finger " << finger << " step " << i;
      EXPECT_EQ(p.pip_flexion_rad, start.pip_flexion_rad);
      EXPECT_EQ(p.dip_flexion_rad, start.dip_flexion_rad);
      EXPECT_EQ(p.abduction_rad, 0.0);
      previous_mcp = p.mcp_flexion_rad;
    }
    const FingerGeometry& g = plan.geometry[static_cast<std::size_t>(finger - 1)];
    EXPECT_EQ(start.pip_flexion_rad, g.white_bend_rad);
    EXPECT_NEAR(start.dip_flexion_rad, g.coupling * g.white_bend_rad, 1e-15);
  }
}

TEST(KeyStroke, ThumbStrikesByAbduction) {
  const Models& m = test::models();
  const double lead = m.params.timing.press_lead_s;
  const FingerMotionPlan plan = test::plan_notes({{60, 1.0, 1.5, 1}}, 600, 0);
  const FingerPose start = pose_at(plan, 1, 600, 1.0 - lead);
  const FingerPose end = pose_at(plan, 1, 600, 1.0);
  EXPECT_GT(end.abduction_rad, start.abduction_rad + 0.05);
  EXPECT_EQ(end.mcp_flexion_rad, start.mcp_flexion_rad);
  EXPECT_EQ(end.pip_flexion_rad, start.pip_flexion_rad);
  EXPECT_EQ(end.dip_flexion_rad, 0.0);
  EXPECT_EQ(end.press_depth, 1.0);
}

TEST(KeyStroke, BlackKeyBendIsChosenBeforeTheStroke) {
  const Models& m = test::models();
  const double lead = m.params.timing.press_lead_s;
  const FingerMotionPlan plan =
      test::plan_notes({{60, 1.0, 1.4, 3}, {61, 2.0, 2.4, 3}}, m.keyboard.x_mm(60), 0);
  const FingerGeometry& g = plan.geometry[2];
  const KeyContact& black = plan.right.fingers[2][1];
  EXPECT_TRUE(black.black);
  const double x = m.keyboard.x_mm(60);
  EXPECT_EQ(pose_at(plan, 3, x, 1.2).pip_flexion_rad, g.white_bend_rad);
  // Shaped during the approach, fixed from the stroke start to the release.
  for (double t : {2.0 - lead, 2.0 - 0.5 * lead, 2.0, 2.3}) {
    EXPECT_EQ(pose_at(plan, 3, x, t).pip_flexion_rad, g.black_bend_rad) << t;
  }
  EXPECT_NE(g.black_bend_rad, g.white_bend_rad);
  const double mid_shape = 0.5 * (black.shape_start_s + black.stroke_start_s);
  const double pip = pose_at(plan, 3, x, mid_shape).pip_flexion_rad;
  EXPECT_GT(pip, std::min(g.black_bend_rad, g.white_bend_rad) - 0.3);
  const FingerPose at_onset = pose_at(plan, 3, x, 2.0);
  EXPECT_EQ(at_onset.press_depth, 1.0);
  EXPECT_EQ(at_onset.contact_z_mm, black.bottom_z_mm);
  EXPECT_LT(black.bottom_z_mm, m.params.keys.black_top_z_mm - 0.5 * m.params.keys.dip_mm);
  EXPECT_GE(black.bottom_z_mm, m.params.keys.black_top_z_mm - m.params.keys.dip_mm);
}

// A key is a lever on its balance rail: the deeper in a pad presses it, the less it travels
// (dip_mm is the travel at the white front edge, or the black key's front). Without a rail
// (pivot_y_mm 0) every key travels the whole dip.
TEST(KeyStroke, KeyTravelShrinksTowardTheBalanceRail) {
  const Models& m = test::models();
  ASSERT_GT(m.params.keys.pivot_y_mm, 0.0);
  const double x = m.keyboard.x_mm(60);
  const FingerMotionPlan plan = test::plan_notes({{60, 1.0, 1.5, 3}, {60, 2.0, 2.5, 5}}, x, 0);
  const KeyContact& middle = plan.right.fingers[2].front();
  const KeyContact& little = plan.right.fingers[4].front();
  const double top = m.params.keys.white_top_z_mm;
  // The little finger lands nearer the front than the long middle finger: it travels further.
  EXPECT_GT(top - little.bottom_z_mm, top - middle.bottom_z_mm);
  EXPECT_DOUBLE_EQ(middle.inv_travel_per_mm, 1.0 / (top - middle.bottom_z_mm));

  FingerMotionParams no_rail = m.params;
  no_rail.keys.pivot_y_mm = 0.0;
  const FingerMotionPlan flat = test::plan_notes({{60, 1.0, 1.5, 3}}, x, 0, no_rail);
  EXPECT_EQ(flat.right.fingers[2].front().bottom_z_mm, top - m.params.keys.dip_mm);
}

}  // namespace
}  // namespace tutti::finger_motion
