// SPDX-License-Identifier: MIT
// One hand passes over the other (pass_over.hpp): the crossing hand is lifted while the hands
// overlap, every key is still struck at its bottom, and hands that stay on their sides are never
// lifted.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include <tutti/finger_motion/plan_pass_over.hpp>
#include "finger_motion_fixture.hpp"

namespace tutti::finger_motion {
namespace {

using components::HandSide;

// Still at from_mm until move_s, then a linear move to to_mm over move_for_s, then still.
spline_motion::HandPath leap_path(double from_mm, double to_mm, double move_s, double move_for_s) {
  spline_motion::Poly5 before;
  before.c[0] = from_mm;
  spline_motion::Poly5 move;
  move.c[0] = from_mm;
  move.c[1] = (to_mm - from_mm) / move_for_s;
  spline_motion::Poly5 after;
  after.c[0] = to_mm;
  return spline_motion::HandPath(spline_motion::SmoothingMode::none, {0.0, move_s, move_s + move_for_s, 1000.0},
                          {before, move, after}, to_mm, true);
}

struct Planned {
  FingerMotionPlan plan;
  spline_motion::HandPath right;
  spline_motion::HandPath left;
};

// After the Polonaise op. 1 no. 4 at 15 s: the left hand holds C#4-E4-G4 while the right hand
// leaps from C#5 over it to F#3, close under it, and strikes that with its index.
Planned right_hand_leaps_over_the_left() {
  const Models& m = test::models();
  Planned p;
  const double index_rest = 0.5 * (m.hand.range(music::Hand::right, 2).lo_mm +
                                   m.hand.range(music::Hand::right, 2).hi_mm);
  const double middle_rest_left = 0.5 * (m.hand.range(music::Hand::left, 3).lo_mm +
                                         m.hand.range(music::Hand::left, 3).hi_mm);
  p.right = leap_path(m.keyboard.x_mm(73) - index_rest, m.keyboard.x_mm(54) - index_rest, 1.1, 0.15);
  p.left = test::constant_path(m.keyboard.x_mm(61) - middle_rest_left);
  const test::TestScore s = test::make_score({{61, 0.5, 3.0, 3, music::Hand::left},
                                              {64, 0.5, 3.0, 2, music::Hand::left},
                                              {67, 0.5, 3.0, 1, music::Hand::left},
                                              {73, 0.5, 1.0, 2, music::Hand::right},
                                              {54, 1.5, 2.0, 2, music::Hand::right}});
  auto plan = plan_finger_motion(s.score, s.plan, p.right, p.left, m.keyboard, m.hand, m.params);
  EXPECT_TRUE(plan.ok()) << (plan.ok() ? "" : plan.error().message);
  if (plan.ok()) p.plan = *plan;
  return p;
}

TEST(PassOver, TheHandThatLeapsIsLiftedOverTheOtherWhileTheyOverlap) {
  const Models& m = test::models();
  const Planned p = right_hand_leaps_over_the_left();
  ASSERT_EQ(p.plan.right.pass_over.lifts.size(), 1u);
  EXPECT_TRUE(p.plan.left.pass_over.lifts.empty());
  const PassOverLift& lift = p.plan.right.pass_over.lifts[0];
  EXPECT_EQ(lift.height_mm, m.params.pass_over.lift_mm);
  // Up before the hands overlap, down after: the leap passes the left hand inside [1.1, 1.25].
  EXPECT_LT(lift.rise_from_s, lift.top_from_s);
  EXPECT_GT(lift.top_from_s, 1.1);
  EXPECT_LT(lift.top_from_s, 1.25);
  EXPECT_GT(lift.down_to_s, lift.top_to_s);
  for (double t = 1.0; t < 2.5; t += 0.01) {
    HandPose right;
    evaluate_hand_pose(p.plan, p.right, HandSide::right, t, right);
    HandPose left;
    evaluate_hand_pose(p.plan, p.left, HandSide::left, t, left);
    const double root_z = p.plan.geometry[2].root_z_mm;
    EXPECT_EQ(left.z_mm, root_z) << t;
    if (t >= lift.top_from_s && t <= lift.top_to_s) {
      EXPECT_EQ(right.z_mm, root_z + lift.height_mm) << t;
    }
    if (t <= lift.rise_from_s || t >= lift.down_to_s) {
      EXPECT_EQ(right.z_mm, root_z) << t;
    }
  }
}

TEST(PassOver, TheLiftRisesAndFallsSmoothly) {
  const Planned p = right_hand_leaps_over_the_left();
  ASSERT_FALSE(p.plan.right.pass_over.lifts.empty());
  const PassOverLift& lift = p.plan.right.pass_over.lifts[0];
  double last = 0.0;
  double fastest = 0.0;
  const double step = 1e-4;
  for (double t = lift.rise_from_s - 0.01; t < lift.down_to_s + 0.01; t += step) {
    const double now = evaluate_pass_over(p.plan.right.pass_over, t);
    EXPECT_GE(now, 0.0);
    EXPECT_LE(now, lift.height_mm);
    fastest = std::max(fastest, std::abs(now - last) / step);
    last = now;
  }
  // A minimum-jerk ease peaks at 1.875 x height / duration.
  const double ease = lift.top_from_s - lift.rise_from_s;
  EXPECT_LT(fastest, 1.875 * lift.height_mm / ease * 1.01);
}

// Landing on F#3 while still over the left hand, the index reaches down from the lifted hand
// (straighter) to the key's bottom, its pad as far into the keys as from a hand at its height.
TEST(PassOver, AFingerOfTheLiftedHandStillStrikesItsKeyBottom) {
  const Planned p = right_hand_leaps_over_the_left();
  ASSERT_FALSE(p.plan.right.pass_over.lifts.empty());
  const KeyContact& c = p.plan.right.fingers[1].at(1);
  ASSERT_EQ(c.key, 54);
  // Still lifted at the onset: the hands overlap where it lands.
  const double lift = evaluate_pass_over(p.plan.right.pass_over, c.onset_s);
  FingerPose pose;
  evaluate_finger_pose(p.plan, HandSide::right, 2, spline_motion::evaluate(p.right, c.onset_s).x_mm,
                       c.onset_s, pose);
  EXPECT_EQ(pose.key, 54);
  EXPECT_EQ(pose.press_depth, 1.0);
  EXPECT_NEAR(pose.contact_z_mm, c.bottom_z_mm, 1e-9);
  EXPECT_GT(lift, 0.0);
  // On the black key's top, behind its front edge, as a finger of a hand at its height lands.
  const KeyHeights& keys = p.plan.keys;
  EXPECT_GT(pose.contact_y_mm, keys.black_front_y_mm) << "lift " << lift;
  EXPECT_NEAR(pose.contact_y_mm, keys.black_front_y_mm + keys.black_press_in_mm, 15.0);
}

TEST(PassOver, HandsOnTheirOwnSidesAreNeverLifted) {
  const Models& m = test::models();
  const double right_x = m.keyboard.x_mm(72);
  const double left_x = m.keyboard.x_mm(48);
  const FingerMotionPlan plan = test::plan_notes({{72, 1.0, 2.0, 3, music::Hand::right},
                                                  {76, 1.5, 2.5, 4, music::Hand::right},
                                                  {48, 1.0, 2.0, 3, music::Hand::left},
                                                  {43, 1.5, 2.5, 5, music::Hand::left}},
                                                 right_x, left_x);
  EXPECT_TRUE(plan.right.pass_over.lifts.empty());
  EXPECT_TRUE(plan.left.pass_over.lifts.empty());
}

TEST(PassOver, NoLiftWithAZeroHeight) {
  const Models& m = test::models();
  FingerMotionParams params = m.params;
  params.pass_over.lift_mm = 0.0;
  const Planned p = right_hand_leaps_over_the_left();
  FingerMotionPlan plan = p.plan;
  plan_pass_over(plan, p.right, p.left, params.pass_over);
  EXPECT_TRUE(plan.right.pass_over.lifts.empty());
  EXPECT_EQ(evaluate_pass_over(plan.right.pass_over, 1.2), 0.0);
}

}  // namespace
}  // namespace tutti::finger_motion
