// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include "key_action_fixture.hpp"

namespace tutti::key_action {
namespace {

TEST(KeySimulation, APreciseStyleSoundsEveryNoteOnTimeAtItsVelocity) {
  const test::Performed p = test::perform_score(test::scale_score(), test::style("precise"), 1);
  ASSERT_EQ(p.result.played.size(), p.score.notes.size());
  for (std::size_t i = 0; i < p.score.notes.size(); ++i) {
    const PlayedNote& played = p.result.played[i];
    SCOPED_TRACE(i);
    ASSERT_EQ(played.outcome, KeyOutcome::sounded);
    EXPECT_NEAR(played.onset_s, p.score.notes[i].onset_s, 0.0005);
    EXPECT_NEAR(played.velocity, p.score.notes[i].velocity, 2);
    EXPECT_GT(played.offset_s, played.onset_s);
  }
}

// The escapement time found by an independent fine scan of the evaluated fingertip: the first
// time the key angle the tip holds reaches the escapement angle.
TEST(KeySimulation, TheNoteSoundsWhenTheFingertipTakesTheKeyPastEscapement) {
  const test::Performed p = test::perform_score(test::scale_score(0.4), test::style("gentle"), 3);
  const KeyAction& action = test::content().action;
  const finger_motion::FingerMotionPlan& plan = p.result.motion->fingers;
  int checked = 0;
  for (std::size_t f = 0; f < 5; ++f) {
    for (const finger_motion::KeyContact& c : plan.right.fingers[f]) {
      const KeyLever& lever = action.lever(c.black);
      const double top = c.black ? plan.keys.black_top_z_mm : plan.keys.white_top_z_mm;
      const double escape = action.escapement_fraction * lever.bed_angle_rad();
      double crossed = std::nan("");
      for (double t = c.stroke_start_s; t <= c.onset_s + 1e-9; t += 1e-5) {
        finger_motion::FingerPose pose;
        finger_motion::evaluate_finger_pose(plan, components::HandSide::right,
                                            static_cast<int>(f) + 1, 0.0, t, pose);
        if (pose.key == c.key && lever.angle_rad(pose.contact_y_mm, top - pose.contact_z_mm) >= escape) {
          crossed = t;
          break;
        }
      }
      const PlayedNote& played = p.result.played[static_cast<std::size_t>(c.note)];
      ASSERT_EQ(played.outcome, KeyOutcome::sounded);
      EXPECT_NEAR(played.onset_s, crossed, 2e-5) << "note " << c.note;
      EXPECT_LT(played.onset_s, c.onset_s);  // before the key bed
      ++checked;
    }
  }
  EXPECT_EQ(checked, 15);
}

TEST(KeySimulation, SlowerFingersSoundLaterAndSofter) {
  PerformanceStyle slow = test::style("precise");
  slow.finger_speed = {0.7, 0.7, 0.7, 0.7, 0.7};
  const test::Performed fast = test::perform_score(test::scale_score(), test::style("precise"), 1);
  const test::Performed late = test::perform_score(test::scale_score(), slow, 1);
  for (std::size_t i = 0; i < fast.score.notes.size(); ++i) {
    SCOPED_TRACE(i);
    ASSERT_EQ(late.result.played[i].outcome, KeyOutcome::sounded);
    EXPECT_GT(late.result.played[i].onset_s, fast.result.played[i].onset_s + 0.005);
    EXPECT_LT(late.result.played[i].velocity, fast.result.played[i].velocity);
  }
}

TEST(KeySimulation, APressTooSlowForTheHammerIsSilent) {
  KeyAction stiff = test::content().action;
  stiff.velocity.silent_below_mm_s = 5000.0;
  stiff.velocity.min_mm_s = 5000.0;
  stiff.velocity.max_mm_s = 6000.0;
  const test::Performed p =
      test::perform_score(test::scale_score(), test::style("precise"), 1, &stiff);
  EXPECT_EQ(p.result.report.too_soft, p.score.notes.size());
  EXPECT_EQ(p.result.report.sounded, 0u);
  EXPECT_TRUE(std::isnan(p.result.played[0].onset_s));
  EXPECT_GT(p.result.played[0].key_speed_mm_s, 0.0);
}

TEST(KeySimulation, AKeyThatHasNotRisenDoesNotStrikeAgain) {
  // Repeated G4s 0.3 s apart: the content's keys spring back in 50 ms and repeat; keys that
  // take 2 s to rise cannot reach their reset angle before the next stroke.
  const music::Score score = test::simple_score(
      {{67, 0.5, 0.25, 80}, {67, 0.8, 0.25, 80}, {67, 1.1, 0.25, 80}, {67, 1.4, 0.25, 80}});
  const test::Performed springy = test::perform_score(score, test::style("precise"), 1);
  EXPECT_EQ(springy.result.report.sounded, 4u);
  KeyAction sluggish = test::content().action;
  sluggish.return_s = 2.0;
  const test::Performed stuck = test::perform_score(score, test::style("precise"), 1, &sluggish);
  EXPECT_EQ(stuck.result.played[0].outcome, KeyOutcome::sounded);
  EXPECT_EQ(stuck.result.report.not_reset, 3u);
}

TEST(KeySimulation, TheDamperFallsAsTheKeyRises) {
  const test::Performed p = test::perform_score(test::scale_score(0.5), test::style("precise"), 1);
  const PerformanceStyle precise = test::style("precise");
  for (std::size_t i = 0; i < p.score.notes.size(); ++i) {
    const double released = p.result.strokes.strokes[i].release_s;
    EXPECT_GE(p.result.played[i].offset_s, released);
    EXPECT_LE(p.result.played[i].offset_s, released + precise.release_s);
  }
}

TEST(KeySimulation, TheSameMotionGivesTheSameNotesBitForBit) {
  const test::Performed a = test::perform_score(test::ode_to_joy(), test::style("beginner"), 7);
  const KeySimulationOptions options;
  const std::vector<PlayedNote> again =
      simulate_keys(a.score, a.plan.fingering, *a.result.motion, test::content().action, options);
  ASSERT_EQ(again.size(), a.result.played.size());
  for (std::size_t i = 0; i < again.size(); ++i) {
    EXPECT_EQ(std::memcmp(&again[i].onset_s, &a.result.played[i].onset_s, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&again[i].offset_s, &a.result.played[i].offset_s, sizeof(double)), 0);
    EXPECT_EQ(again[i].velocity, a.result.played[i].velocity);
    EXPECT_EQ(again[i].outcome, a.result.played[i].outcome);
  }
}

}  // namespace
}  // namespace tutti::key_action
