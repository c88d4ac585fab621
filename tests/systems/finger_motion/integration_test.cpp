// SPDX-License-Identifier: MIT
// Ode to Joy end to end: load, finger (plan_score), hand paths (plan_hand_path), finger motion;
// then a 60 fps sweep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include "finger_motion_fixture.hpp"
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/spline_motion/smoothing.hpp>

namespace tutti::finger_motion {
namespace {

// plan_hand_path rejects corridors that touch in time with disjoint ranges (no time to move);
// systems/piano_performance will repair that properly. Here: end the earlier one 5 ms early.
piano_model::HandCorridors trimmed(piano_model::HandCorridors corridors) {
  for (std::size_t i = 0; i + 1 < corridors.size(); ++i) {
    piano_model::HandCorridor& a = corridors[i];
    const piano_model::HandCorridor& b = corridors[i + 1];
    const bool disjoint = a.hi_mm < b.lo_mm || b.hi_mm < a.lo_mm;
    if (disjoint && a.end_s >= b.start_s) a.end_s = std::max(a.start_s, b.start_s - 0.005);
  }
  return corridors;
}

TEST(FingerMotionIntegration, OdeToJoy) {
  auto score = music::load_score(std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "music" /
                                 "ode_to_joy.musicxml");
  ASSERT_TRUE(score.ok()) << score.error().message;
  auto model = fingering_planner::load_fingering_model("default", "", test::content_dir());
  ASSERT_TRUE(model.ok()) << model.error().message;
  auto fingering = fingering_planner::plan_score(*score, *model);
  ASSERT_TRUE(fingering.ok()) << fingering.error().message;
  auto right = spline_motion::plan_hand_path(trimmed(fingering->right.corridors));
  ASSERT_TRUE(right.ok()) << right.error().message;
  auto left = spline_motion::plan_hand_path(trimmed(fingering->left.corridors));
  ASSERT_TRUE(left.ok()) << left.error().message;
  auto plan = plan_finger_motion(*score, *fingering, *right, *left, model->keyboard, model->hand,
                                 test::models().params);
  ASSERT_TRUE(plan.ok()) << plan.error().message;

  std::size_t contacts = 0;
  for (const HandFingerPlan* hand : {&plan->right, &plan->left}) {
    const spline_motion::HandPath& path = hand->side == components::HandSide::left ? *left : *right;
    HandPose pose;
    for (std::size_t f = 0; f < 5; ++f) {
      for (const KeyContact& c : hand->fingers[f]) {
        ++contacts;
        evaluate_hand_pose(*plan, path, hand->side, c.onset_s, pose);
        EXPECT_EQ(pose.fingers[f].press_depth, 1.0);
        EXPECT_EQ(pose.fingers[f].tip_x_mm, c.x_mm);
        // The hand path keeps every finger within reach: spreads stay moderate.
        EXPECT_LT(std::abs(pose.fingers[f].spread_rad), 1.0)
            << "finger " << f + 1 << " at " << c.onset_s;
      }
    }
    for (double t = 0; t < score->duration_s() + 1.0; t += 1.0 / 60) {
      evaluate_hand_pose(*plan, path, hand->side, t, pose);
      for (const FingerPose& p : pose.fingers) {
        ASSERT_TRUE(std::isfinite(p.spread_rad) && std::isfinite(p.mcp_flexion_rad) &&
                    std::isfinite(p.abduction_rad) && std::isfinite(p.tip_z_mm));
        ASSERT_LT(std::abs(p.spread_rad), 1.2) << t;
      }
    }
  }
  EXPECT_GT(contacts, 20U);
}

}  // namespace
}  // namespace tutti::finger_motion
