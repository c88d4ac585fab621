// SPDX-License-Identifier: MIT
// evaluate_hand_pose is a pure function of (plan, path, t): deterministic, seek-order independent.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include "finger_motion_fixture.hpp"

namespace tutti::finger_motion {
namespace {

using components::HandSide;

bool same_bits(const HandPose& a, const HandPose& b) {
  auto same = [](double x, double y) { return std::memcmp(&x, &y, sizeof(double)) == 0; };
  if (!same(a.x_mm, b.x_mm) || !same(a.v_x_mm_per_s, b.v_x_mm_per_s)) return false;
  for (std::size_t f = 0; f < 5; ++f) {
    const FingerPose& p = a.fingers[f];
    const FingerPose& q = b.fingers[f];
    if (!same(p.spread_rad, q.spread_rad) || !same(p.abduction_rad, q.abduction_rad) ||
        !same(p.mcp_flexion_rad, q.mcp_flexion_rad) ||
        !same(p.pip_flexion_rad, q.pip_flexion_rad) ||
        !same(p.dip_flexion_rad, q.dip_flexion_rad) || !same(p.press_depth, q.press_depth) ||
        !same(p.tip_x_mm, q.tip_x_mm) || !same(p.tip_y_mm, q.tip_y_mm) ||
        !same(p.tip_z_mm, q.tip_z_mm) || p.key != q.key) {
      return false;
    }
  }
  return true;
}

FingerMotionPlan scale_plan() {
  std::vector<test::TestNote> notes;
  const int keys[] = {60, 62, 64, 65, 67, 69, 71, 72};
  const int fingers[] = {1, 2, 3, 1, 2, 3, 4, 5};
  for (int i = 0; i < 8; ++i) {
    notes.push_back({keys[i], 0.5 + 0.25 * i, 0.5 + 0.25 * i + 0.24, fingers[i]});
  }
  return test::plan_notes(notes, test::models().keyboard.x_mm(64), 0);
}

TEST(EvaluateHandPose, SameTimeSameBitsInAnyOrder) {
  const FingerMotionPlan plan = scale_plan();
  const spline_motion::HandPath path = test::constant_path(test::models().keyboard.x_mm(64));
  HandPose first;
  HandPose again;
  HandPose other;
  for (double t : {0.0, 0.6, 0.749, 1.1, 2.0, 2.7, 5.0}) {
    evaluate_hand_pose(plan, path, HandSide::right, t, first);
    evaluate_hand_pose(plan, path, HandSide::right, 2.7 - t, other);  // seek elsewhere
    evaluate_hand_pose(plan, path, HandSide::right, t, again);
    EXPECT_TRUE(same_bits(first, again)) << t;
  }
  // Forward at 60 fps vs backwards: identical per frame.
  std::vector<HandPose> forward(200);
  for (int i = 0; i < 200; ++i) {
    evaluate_hand_pose(plan, path, HandSide::right, i / 60.0, forward[static_cast<std::size_t>(i)]);
  }
  for (int i = 199; i >= 0; --i) {
    evaluate_hand_pose(plan, path, HandSide::right, i / 60.0, again);
    EXPECT_TRUE(same_bits(forward[static_cast<std::size_t>(i)], again)) << i;
  }
}

TEST(EvaluateHandPose, EveryNoteIsPressedAtItsOnsetAndValuesAreFinite) {
  const FingerMotionPlan plan = scale_plan();
  const spline_motion::HandPath path = test::constant_path(test::models().keyboard.x_mm(64));
  HandPose pose;
  for (std::size_t f = 0; f < 5; ++f) {
    for (const KeyContact& c : plan.right.fingers[f]) {
      evaluate_hand_pose(plan, path, HandSide::right, c.onset_s, pose);
      EXPECT_EQ(pose.fingers[f].press_depth, 1.0);
      EXPECT_EQ(pose.fingers[f].tip_x_mm, c.x_mm);
      EXPECT_EQ(pose.fingers[f].key, c.key);
    }
  }
  for (int i = 0; i < 300; ++i) {
    evaluate_hand_pose(plan, path, HandSide::right, i / 100.0, pose);
    for (const FingerPose& p : pose.fingers) {
      EXPECT_TRUE(std::isfinite(p.spread_rad) && std::isfinite(p.mcp_flexion_rad) &&
                  std::isfinite(p.abduction_rad) && std::isfinite(p.tip_y_mm));
      EXPECT_LT(std::abs(p.spread_rad), 1.2);
      EXPECT_GE(p.press_depth, 0.0);
      EXPECT_LE(p.press_depth, 1.0);
    }
  }
}

TEST(EvaluateHandPose, NonFiniteTimeIsHarmless) {
  const FingerMotionPlan plan = scale_plan();
  const spline_motion::HandPath path = test::constant_path(600);
  HandPose pose;
  for (double t :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()}) {
    evaluate_hand_pose(plan, path, HandSide::right, t, pose);
    for (const FingerPose& p : pose.fingers) {
      EXPECT_TRUE(std::isfinite(p.mcp_flexion_rad));
      EXPECT_TRUE(std::isfinite(p.tip_x_mm));
    }
  }
}

TEST(EvaluateHandPose, EmptyPlanRestsEveryFinger) {
  const FingerMotionPlan plan = test::plan_notes({}, 600, 300);
  HandPose pose;
  evaluate_hand_pose(plan, test::constant_path(300), HandSide::left, 1.0, pose);
  EXPECT_EQ(pose.x_mm, 300.0);
  for (std::size_t f = 0; f < 5; ++f) {
    EXPECT_EQ(pose.fingers[f].press_depth, 0.0);
    EXPECT_EQ(pose.fingers[f].spread_rad, 0.0);
    EXPECT_EQ(pose.fingers[f].tip_x_mm, 300.0 + plan.left.rest_offset_mm[f]);
  }
}

TEST(PlanFingerMotion, RejectsMismatchedOrBadInput) {
  const Models& m = test::models();
  test::TestScore s = test::make_score({{60, 1.0, 1.5, 3}});
  s.plan.fingers.clear();
  auto plan = plan_finger_motion(s.score, s.plan, test::constant_path(0), test::constant_path(0),
                                 m.keyboard, m.hand, m.params);
  ASSERT_FALSE(plan.ok());
  EXPECT_NE(plan.error().message.find("1 notes"), std::string::npos);
  s = test::make_score({{60, 1.0, 0.5, 3}});
  plan = plan_finger_motion(s.score, s.plan, test::constant_path(0), test::constant_path(0),
                            m.keyboard, m.hand, m.params);
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().message, "score: note 0: offset before onset");
  s = test::make_score({{60, 1.0, 1.5, 7}});
  plan = plan_finger_motion(s.score, s.plan, test::constant_path(0), test::constant_path(0),
                            m.keyboard, m.hand, m.params);
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.error().message, "score: note 0: finger outside 0..5");
}

TEST(PlanFingerMotion, SameOnsetOnOneFingerMerges) {
  const FingerMotionPlan plan = test::plan_notes({{60, 1.0, 1.5, 3}, {62, 1.0, 1.8, 3}}, 600, 0);
  ASSERT_EQ(plan.right.fingers[2].size(), 1U);
  EXPECT_EQ(plan.right.fingers[2][0].key, 60);
  EXPECT_EQ(plan.right.fingers[2][0].offset_s, 1.8);
}

}  // namespace
}  // namespace tutti::finger_motion
