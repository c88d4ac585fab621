// SPDX-License-Identifier: MIT
// The ensemble's body motion (ensemble_variation/ensemble_plan.hpp, evaluate_body_motion.hpp)
// on a 4/4 score at 120 BPM (a beat is 0.5 s) with hand-made breath plans: cue timing, breath
// motion on the breath plan's times, weight shifts on bar lines and phrase boundaries, seeds that
// move differently, and a pose that depends on t alone.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "ensemble_fixture.hpp"
#include <tutti/ensemble_variation/ensemble_plan.hpp>
#include <tutti/ensemble_variation/evaluate_body_motion.hpp>

namespace tutti::ensemble_variation {
namespace {

using test::breaths;
using test::four_four;
using test::player;

TEST(BodyMotion, TheLeadCuesOneBeatBeforeTheFirstEntranceAndTheOthersAnswerLate) {
  const music::Score score = four_four();
  const test::Breaths none;
  std::vector<PerformerInput> inputs = {player(score, none, 1, true),
                                        player(score, none, 2, false)};
  inputs[0].params.cue_strength = 1.0;
  inputs[1].params.cue_strength = 1.0;
  auto plan = plan_ensemble(inputs);
  ASSERT_TRUE(plan) << plan.error().message;
  EXPECT_EQ(plan->lead, 0);
  EXPECT_DOUBLE_EQ(plan->entrance_s, 2.0);
  const PerformerMotionPlan& lead = plan->performers[0];
  const PerformerMotionPlan& follower = plan->performers[1];
  // Sampled every millisecond: where the bell is highest and the knees bend most.
  double lift_peak = 0.0, lift_at = -1.0, knees_peak = 0.0, knees_at = -1.0;
  double follower_peak = 0.0, follower_at = -1.0;
  for (int ms = 0; ms < 3000; ++ms) {
    const double t = ms / 1000.0;
    const components::BodyMotion m = evaluate_body_motion(lead, t);
    if (t < 1.5) {
      EXPECT_EQ(m.bell_lift_rad, 0.0f) << t;
    }
    if (m.bell_lift_rad > lift_peak) lift_peak = m.bell_lift_rad, lift_at = t;
    if (m.knee_flex_m > knees_peak) knees_peak = m.knee_flex_m, knees_at = t;
    const components::BodyMotion f = evaluate_body_motion(follower, t);
    if (f.bell_lift_rad > follower_peak) follower_peak = f.bell_lift_rad, follower_at = t;
  }
  EXPECT_NEAR(lift_at, 1.75, 0.002);  // half a beat into the beat before the entrance
  EXPECT_NEAR(knees_at, 2.0, 0.002);  // the dip lands on the entrance
  EXPECT_NEAR(lift_peak, 0.14, 1e-3);
  EXPECT_NEAR(knees_peak, 0.03, 1e-4);
  // The follower answers with a smaller gesture, 60..140 ms later.
  EXPECT_GT(follower_at - lift_at, 0.059);
  EXPECT_LT(follower_at - lift_at, 0.141);
  EXPECT_LT(follower_peak, 0.5 * lift_peak);
}

TEST(BodyMotion, BreathingMovesTheBodyExactlyWhenTheBreathPlanBreathes) {
  const music::Score score = four_four();
  // Both players breathe in the same rest (the same rule window); the first also prepares.
  const test::Breaths first = breaths({{9.0, 9.5, 10.0}});
  const test::Breaths second = breaths({{9.5, 9.5, 10.0}});
  std::vector<PerformerInput> inputs = {player(score, first, 3, false),
                                        player(score, second, 4, false)};
  inputs[0].params.breath_depth = 1.0;
  inputs[1].params.breath_depth = 0.2;
  auto plan = plan_ensemble(inputs);
  ASSERT_TRUE(plan);
  double peak_at = -1.0, peak = 0.0;
  for (int ms = 8000; ms < 11000; ++ms) {
    const double t = ms / 1000.0;
    const components::BodyMotion a = evaluate_body_motion(plan->performers[0], t);
    const components::BodyMotion b = evaluate_body_motion(plan->performers[1], t);
    const bool in_first = t > 9.0 && t < 10.35;
    const bool in_second = t > 9.5 && t < 10.35;
    EXPECT_EQ(a.lean_back_rad > 0.0f, in_first) << t;
    EXPECT_EQ(b.lean_back_rad > 0.0f, in_second) << t;
    EXPECT_EQ(a.shoulder_lift_m > 0.0f, in_first) << t;
    if (a.lean_back_rad > peak) peak = a.lean_back_rad, peak_at = t;
    // Together in time, not alike in size.
    if (in_second && t > 9.7 && t < 10.2) {
      EXPECT_GT(a.lean_back_rad, 1.5f * b.lean_back_rad) << t;
    }
  }
  EXPECT_NEAR(peak_at, 10.0, 0.002);  // fullest at the end of the inhale
  EXPECT_NEAR(peak, 0.0785, 1e-3);    // 4.5 degrees at full depth
}

TEST(BodyMotion, WeightShiftsOnlyAcrossTheBeatAfterABarLine) {
  const music::Score score = four_four();
  const test::Breaths none;
  std::vector<PerformerInput> inputs = {player(score, none, 5, false)};
  inputs[0].params.weight_shift_rate = 1.0;  // every bar (2 s at 120 BPM in 4/4)
  auto plan = plan_ensemble(inputs);
  ASSERT_TRUE(plan);
  const PerformerMotionPlan& p = plan->performers[0];
  ASSERT_GT(p.weight_shifts.size(), 10u);
  float previous = evaluate_body_motion(p, 0.0).hips_shift_m;
  for (int ms = 1; ms < 20000; ++ms) {
    const double t = ms / 1000.0;
    const float now = evaluate_body_motion(p, t).hips_shift_m;
    const double into_bar = std::fmod(t, 2.0);
    if (into_bar > 0.501 && into_bar < 1.999) {
      EXPECT_EQ(now, previous) << t;
    }
    previous = now;
  }
  // From one foot to the other, bar after bar.
  EXPECT_EQ(p.weight_shifts[0].to_m, -p.weight_shifts[1].to_m);
  EXPECT_NEAR(std::abs(evaluate_body_motion(p, 2.6).hips_shift_m),
              std::abs(evaluate_body_motion(p, 4.6).hips_shift_m), 1e-6);
}

// A breath in a rest starts a phrase: the weight goes over to the other foot across its first
// beat, whatever the bar lines say; a catch breath does not, and a bar line's shift near a
// phrase's gives way to it.
TEST(BodyMotion, WeightShiftsAtPhraseBoundaries) {
  const music::Score score = four_four();  // 120 BPM: a beat is 0.5 s, a bar 2 s
  test::Breaths plan = breaths({{9.0, 9.3, 10.0}, {14.5, 14.5, 14.8}, {21.1, 21.1, 21.6}});
  plan[1].phrase = false;  // a catch-breath
  std::vector<PerformerInput> inputs = {player(score, plan, 5, false)};
  inputs[0].params.weight_shift_rate = 0.0;  // bar shifts every 8 bars (16 s) only
  auto ensemble = plan_ensemble(inputs);
  ASSERT_TRUE(ensemble);
  const auto& shifts = ensemble->performers[0].weight_shifts;
  auto starts_at = [&](double t) {
    return std::any_of(shifts.begin(), shifts.end(),
                       [&](const WeightShift& w) { return std::abs(w.start_s - t) < 1e-9; });
  };
  EXPECT_TRUE(starts_at(9.3)) << "the phrase after the rest at 9 s";
  EXPECT_TRUE(starts_at(21.1));
  EXPECT_FALSE(starts_at(14.5)) << "a catch breath is not a phrase boundary";
  EXPECT_TRUE(starts_at(16.0)) << "the 8-bar line";
  for (std::size_t i = 0; i < shifts.size(); ++i) {
    EXPECT_LT(shifts[i].start_s, shifts[i].end_s);
    EXPECT_LE(shifts[i].end_s - shifts[i].start_s, 0.5 + 1e-9) << "one beat at most";
    if (i > 0) {
      EXPECT_LE(shifts[i - 1].end_s, shifts[i].start_s) << "not overlapping";
      EXPECT_EQ(shifts[i].from_m, shifts[i - 1].to_m) << "from one foot to the other";
    }
  }
  const PerformerMotionPlan& p = ensemble->performers[0];
  EXPECT_NE(evaluate_body_motion(p, 9.2).hips_shift_m, evaluate_body_motion(p, 9.9).hips_shift_m);
}

// Root mean square over the piece of the difference of two players' sway, twist, head and
// weight (radians and metres x 10, so both matter), relative to the motion's own size.
double relative_difference(const PerformerMotionPlan& a, const PerformerMotionPlan& b) {
  double diff = 0.0, size = 0.0;
  for (int ms = 0; ms < 30000; ms += 10) {
    const components::BodyMotion x = evaluate_body_motion(a, ms / 1000.0);
    const components::BodyMotion y = evaluate_body_motion(b, ms / 1000.0);
    const double dx[] = {x.sway_rad - y.sway_rad, x.twist_rad - y.twist_rad,
                         x.head_nod_rad - y.head_nod_rad, 10.0 * (x.hips_shift_m - y.hips_shift_m)};
    const double sx[] = {x.sway_rad, x.twist_rad, x.head_nod_rad, 10.0 * x.hips_shift_m};
    for (int k = 0; k < 4; ++k) {
      diff += dx[k] * dx[k];
      size += sx[k] * sx[k];
    }
  }
  return std::sqrt(diff / size);
}

TEST(BodyMotion, DifferentSeedsMoveVisiblyDifferentlyAndTheSameSeedIdentically) {
  const music::Score score = four_four();
  const test::Breaths none;
  auto one = plan_ensemble({player(score, none, 100, false), player(score, none, 100, false)});
  ASSERT_TRUE(one);
  EXPECT_EQ(relative_difference(one->performers[0], one->performers[1]), 0.0);
  for (std::uint64_t seed = 101; seed < 111; ++seed) {
    auto two = plan_ensemble({player(score, none, 100, false), player(score, none, seed, false)});
    ASSERT_TRUE(two);
    EXPECT_GT(relative_difference(two->performers[0], two->performers[1]), 0.5) << seed;
  }
}

TEST(BodyMotion, ThePoseAtTDependsOnTAlone) {
  const music::Score score = four_four();
  const test::Breaths plan_breaths = breaths({{3.0, 3.5, 4.0}, {11.0, 11.2, 11.6}});
  auto plan = plan_ensemble({player(score, plan_breaths, 9, true)});
  ASSERT_TRUE(plan);
  const PerformerMotionPlan& p = plan->performers[0];
  std::vector<components::BodyMotion> forward;
  for (int k = 0; k < 600; ++k) forward.push_back(evaluate_body_motion(p, k / 30.0));
  for (int k = 599; k >= 0; k -= 7) {
    const components::BodyMotion again = evaluate_body_motion(p, k / 30.0);
    EXPECT_EQ(std::memcmp(&again, &forward[static_cast<std::size_t>(k)], sizeof again), 0) << k;
  }
  const components::BodyMotion nan = evaluate_body_motion(p, std::nan(""));
  EXPECT_EQ(nan.sway_rad, 0.0f);
}

TEST(BodyMotion, APerformerWithoutAScoreIsAnError) {
  PerformerInput in;
  auto plan = plan_ensemble({in});
  ASSERT_FALSE(plan);
  EXPECT_EQ(plan.error().message, "ensemble: a performer has no score");
}

}  // namespace
}  // namespace tutti::ensemble_variation
