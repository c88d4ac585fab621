// SPDX-License-Identifier: MIT
// Spread angle: theta = atan(d / y), 0 above the rest line, mirrored for the left hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include "finger_motion_fixture.hpp"

namespace tutti::finger_motion {
namespace {

using components::HandSide;
using test::TestNote;

TEST(FingerGeometry, SpreadIsZeroRightAboveTheKey) {
  const double key_x = test::models().keyboard.x_mm(60);
  // Middle finger: its rest line is the hand reference point itself.
  const FingerMotionPlan plan = test::plan_notes({{60, 1.0, 1.5, 3}}, key_x, 300.0);
  FingerPose pose;
  evaluate_finger_pose(plan, HandSide::right, 3, key_x, 1.0, pose);
  EXPECT_EQ(pose.spread_rad, 0.0);
  EXPECT_EQ(pose.tip_x_mm, key_x);
  // Index finger with the hand placed so its rest line passes through the key.
  const double hand_x = key_x - plan.right.rest_offset_mm[1];
  const FingerMotionPlan plan2 = test::plan_notes({{60, 1.0, 1.5, 2}}, hand_x, 300.0);
  evaluate_finger_pose(plan2, HandSide::right, 2, hand_x, 1.2, pose);
  EXPECT_NEAR(pose.spread_rad, 0.0, 1e-12);
}

TEST(FingerGeometry, SpreadMagnitudeIsAtanOfOffsetOverReach) {
  const Models& m = test::models();
  const double key_x = m.keyboard.x_mm(64);
  const double hand_x = key_x - 30.0;  // finger 3 reaches 30 mm toward the little finger
  const FingerMotionPlan plan = test::plan_notes({{64, 1.0, 1.5, 3}}, hand_x, 300.0);
  FingerPose pose;
  evaluate_finger_pose(plan, HandSide::right, 3, hand_x, 1.2, pose);
  const double reach = pose.tip_y_mm - plan.geometry[2].root_y_mm;
  EXPECT_GT(reach, 30.0);
  EXPECT_NEAR(pose.spread_rad, std::atan(30.0 / reach), 1e-12);
  EXPECT_GT(pose.spread_rad, 0.0);
}

TEST(FingerGeometry, LeftHandMirrorsTheSign) {
  const Models& m = test::models();
  const double key_x = m.keyboard.x_mm(48);
  const double hand_x = key_x - 25.0;  // key 25 mm to the right of both hands' middle finger
  // Both hands in one place all along would have one lifted over the other (pass_over.hpp),
  // its fingers reaching down straighter: switched off here, where only the mirror matters.
  FingerMotionParams params = m.params;
  params.pass_over.lift_mm = 0.0;
  const FingerMotionPlan plan = test::plan_notes(
      {{48, 1.0, 1.5, 3, music::Hand::right}, {48, 3.0, 3.5, 3, music::Hand::left}}, hand_x,
      hand_x, params);
  FingerPose right;
  FingerPose left;
  evaluate_finger_pose(plan, HandSide::right, 3, hand_x, 1.2, right);
  evaluate_finger_pose(plan, HandSide::left, 3, hand_x, 3.2, left);
  EXPECT_GT(right.spread_rad, 0.0);  // right hand: +x is toward the little finger
  EXPECT_EQ(left.spread_rad, -right.spread_rad);
  EXPECT_EQ(left.tip_x_mm, right.tip_x_mm);
}

TEST(FingerGeometry, MinJerkProfile) {
  EXPECT_EQ(min_jerk(0.0), 0.0);
  EXPECT_EQ(min_jerk(1.0), 1.0);
  EXPECT_DOUBLE_EQ(min_jerk(0.5), 0.5);
  EXPECT_EQ(min_jerk(-1.0), 0.0);
  EXPECT_EQ(min_jerk(2.0), 1.0);
}

TEST(FingerGeometry, StrokeSolutionReachesTheWantedDrop) {
  const FingerGeometry& g = test::models().params.fingers[2];
  const ChainShape shape = chain_shape(g, g.white_bend_rad);
  for (double drop : {10.0, 30.0, 50.0}) {
    const StrokeSolution s = solve_stroke(shape, drop);
    // Forward kinematics of the planar chain with the solved joint 1.
    const double p1 = s.joint1_rad;
    const double p2 = p1 + shape.bend_rad;
    const double p3 = p2 + shape.joint3_rad;
    const double y = g.phalanges_mm[0] * std::cos(p1) + g.phalanges_mm[1] * std::cos(p2) +
                     g.phalanges_mm[2] * std::cos(p3);
    const double z = g.phalanges_mm[0] * std::sin(p1) + g.phalanges_mm[1] * std::sin(p2) +
                     g.phalanges_mm[2] * std::sin(p3);
    EXPECT_NEAR(z, drop, 1e-9);
    EXPECT_NEAR(y, s.reach_y_mm, 1e-9);
  }
}

TEST(FingerGeometry, StrokeAngleIsAsinOfTheDropMinusTheChainAngle) {
  // solve_stroke's single atan2 against the textbook form, for every finger over the bends a
  // finger takes and drops from above the root to beyond reach (clamped to +-R).
  for (const FingerGeometry& g : test::models().params.fingers) {
    for (double bend = -0.2; bend <= 1.6; bend += 0.05) {
      const ChainShape shape = chain_shape(g, bend);
      const double reach = std::hypot(shape.forward_mm, shape.down_mm);
      const double alpha = std::atan2(shape.down_mm, shape.forward_mm);
      // Not within 0.1 % of +-R: there d(joint1)/d(drop) = 1 / sqrt(R^2 - drop^2) is unbounded
      // and any two forms differ by their rounding amplified.
      for (double fraction : {-1.5, -1.0001, -0.999, -0.9, -0.6, -0.3, -0.1, 0.0, 0.2, 0.5, 0.8,
                              0.95, 0.999, 1.0001, 2.0}) {
        const double drop = fraction * reach;
        const double d = std::clamp(drop, -reach, reach);
        const StrokeSolution s = solve_stroke(shape, drop);
        EXPECT_NEAR(s.joint1_rad, std::asin(d / reach) - alpha, 1e-9) << bend << " " << drop;
        EXPECT_NEAR(s.reach_y_mm, std::sqrt(std::max(reach * reach - d * d, 0.0)), 1e-9)
            << bend << " " << drop;
      }
    }
  }
}

}  // namespace
}  // namespace tutti::finger_motion
