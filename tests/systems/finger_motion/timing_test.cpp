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

// Mozart K. 545 at 142.125 s: the left thumb lets D4 go as the right thumb strikes C4, a whole
// tone below it, on the left hand's side. The left thumb is up before the right one comes down.
TEST(FingerTiming, AKeyIsLetGoBeforeTheOtherHandStrikesBesideIt) {
  const Models& m = test::models();
  const StrokeTiming& timing = m.params.timing;
  const double x = m.keyboard.x_mm(61);
  const FingerMotionPlan plan = test::plan_notes(
      {{62, 1.0, 1.5, 1, music::Hand::left}, {60, 1.5, 2.0, 1, music::Hand::right}}, x, x);
  const KeyContact& held = plan.left.fingers[0].at(0);
  const KeyContact& struck = plan.right.fingers[0].at(0);
  EXPECT_DOUBLE_EQ(held.release_end_s, struck.stroke_start_s);
  EXPECT_DOUBLE_EQ(held.offset_s, 1.5 - timing.press_lead_s - timing.release_s);
  FingerPose pose;
  evaluate_finger_pose(plan, HandSide::left, 1, x, struck.stroke_start_s, pose);
  EXPECT_EQ(pose.key, -1);
  EXPECT_EQ(pose.press_depth, 0.0);
  // The striking hand's own note keeps its written length.
  EXPECT_DOUBLE_EQ(struck.offset_s, 2.0);
}

TEST(FingerTiming, AStrikeOnTheOtherHandsOwnSideLeavesTheHeldKeyAlone) {
  const Models& m = test::models();
  // The right hand holds G4 while the left strikes E4 below it (3 semitones, its own side), and
  // the left holds C4 while the right strikes D#4 above it: both keys are held as written.
  const FingerMotionPlan plan =
      test::plan_notes({{67, 1.0, 1.5, 1, music::Hand::right},
                        {64, 1.5, 2.0, 1, music::Hand::left},
                        {60, 3.0, 3.5, 1, music::Hand::left},
                        {63, 3.5, 4.0, 1, music::Hand::right}},
                       m.keyboard.x_mm(67), m.keyboard.x_mm(62));
  EXPECT_DOUBLE_EQ(plan.right.fingers[0].at(0).offset_s, 1.5);
  EXPECT_DOUBLE_EQ(plan.left.fingers[0].at(1).offset_s, 3.5);
}

// A crossed strike long after the key went down, but within the lead and rise of its offset,
// never makes the key let go before it was struck.
TEST(FingerTiming, LettingGoEarlyNeverEndsAKeyBeforeItsOnset) {
  const Models& m = test::models();
  const double x = m.keyboard.x_mm(61);
  const FingerMotionPlan plan = test::plan_notes(
      {{62, 1.0, 1.04, 1, music::Hand::left}, {61, 1.05, 1.5, 1, music::Hand::right}}, x, x);
  const KeyContact& held = plan.left.fingers[0].at(0);
  EXPECT_DOUBLE_EQ(held.offset_s, held.onset_s);
  EXPECT_GT(held.release_end_s, held.offset_s);
}

}  // namespace
}  // namespace tutti::finger_motion
