// SPDX-License-Identifier: MIT
// Between notes the finger stays, then moves late and quickly (minimum jerk) to arrive at onset.
#include <gtest/gtest.h>

#include <cmath>

#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include "finger_motion_fixture.hpp"

namespace tutti::finger_motion {
namespace {

using components::HandSide;

double tip_x(const FingerMotionPlan& plan, double hand_x, double t) {
  FingerPose pose;
  evaluate_finger_pose(plan, HandSide::right, 2, hand_x, t, pose);
  return pose.tip_x_mm;
}

TEST(FingerTiming, StaysThenMovesLateAndArrivesAtOnset) {
  const Models& m = test::models();
  const double from = m.keyboard.x_mm(60);
  const double to = m.keyboard.x_mm(64);
  const double hand_x = from + 10.0;
  const FingerMotionPlan plan = test::plan_notes({{60, 1.0, 1.9, 2}, {64, 2.0, 2.5, 2}}, hand_x, 0);
  const KeyContact& next = plan.right.fingers[1][1];
  // Released at 1.9 (before the next stroke at 1.95): the move starts at the release, late.
  EXPECT_DOUBLE_EQ(next.move_start_s, 1.9);
  EXPECT_DOUBLE_EQ(next.stroke_start_s, 1.95);
  for (double t : {1.0, 1.3, 1.85, 1.9}) EXPECT_EQ(tip_x(plan, hand_x, t), from) << t;
  EXPECT_EQ(tip_x(plan, hand_x, 2.0), to);
  const double h = 1e-5;
  const double v_start = (tip_x(plan, hand_x, 1.9 + h) - tip_x(plan, hand_x, 1.9)) / h;
  const double v_end = (tip_x(plan, hand_x, 2.0) - tip_x(plan, hand_x, 2.0 - h)) / h;
  const double v_mid = (tip_x(plan, hand_x, 1.95 + h) - tip_x(plan, hand_x, 1.95 - h)) / (2 * h);
  EXPECT_NEAR(v_start, 0.0, 1e-3);
  EXPECT_NEAR(v_end, 0.0, 1e-3);
  // Peak speed of a minimum-jerk move: 1.875 x distance / duration.
  EXPECT_NEAR(v_mid, 1.875 * (to - from) / 0.1, 1e-2 * std::abs(v_mid));
  EXPECT_NEAR(tip_x(plan, hand_x, 1.95), 0.5 * (from + to), 1e-9);
}

TEST(FingerTiming, MoveDurationIsBounded) {
  const Models& m = test::models();
  const StrokeTiming& timing = m.params.timing;
  // Far apart in time and space: the move takes at most move_max_s and ends at the onset.
  const FingerMotionPlan far = test::plan_notes({{40, 1.0, 1.2, 2}, {90, 5.0, 5.5, 2}}, 600, 0);
  const KeyContact& c = far.right.fingers[1][1];
  EXPECT_NEAR(c.onset_s - c.move_start_s, timing.move_max_s, 1e-12);
  // Neighbouring keys: at least move_min_s.
  const FingerMotionPlan near = test::plan_notes({{60, 1.0, 1.2, 2}, {62, 5.0, 5.5, 2}}, 600, 0);
  const KeyContact& d = near.right.fingers[1][1];
  EXPECT_GE(d.onset_s - d.move_start_s, timing.move_min_s);
  EXPECT_LT(d.onset_s - d.move_start_s, timing.move_max_s);
}

TEST(FingerTiming, RelaxesTowardRestAfterRelease) {
  const Models& m = test::models();
  const double key_x = m.keyboard.x_mm(60);
  const double hand_x = key_x + 40.0;
  const FingerMotionPlan plan = test::plan_notes({{60, 1.0, 1.5, 2}}, hand_x, 0);
  const double rest = hand_x + plan.right.rest_offset_mm[1];
  const double d0 = std::abs(tip_x(plan, hand_x, 1.5) - rest);
  const double d1 =
      std::abs(tip_x(plan, hand_x, 1.5 + m.params.timing.relax_time_constant_s) - rest);
  EXPECT_NEAR(d1, d0 * std::exp(-1.0), 1e-9);
  EXPECT_LT(std::abs(tip_x(plan, hand_x, 10.0) - rest), 1e-6);
}

TEST(FingerTiming, SameFingerLegatoRepeatReleasesBeforeTheNextStroke) {
  const FingerMotionPlan plan = test::plan_notes({{60, 1.0, 1.2, 3}, {60, 1.2, 1.4, 3}}, 600, 0);
  const auto& contacts = plan.right.fingers[2];
  ASSERT_EQ(contacts.size(), 2U);
  EXPECT_LE(contacts[0].offset_s, contacts[1].stroke_start_s);
  EXPECT_GE(contacts[0].offset_s, contacts[0].onset_s);
}

}  // namespace
}  // namespace tutti::finger_motion
