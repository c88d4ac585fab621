// SPDX-License-Identifier: MIT
// The editor's cues (EnsembleOptions::cues_s) and expressions (ExpressionSpan) on the 4/4 score
// at 120 BPM of ensemble_fixture.hpp: automatic = one cue at the first entrance, an explicit list
// gives exactly its cues (none for an empty list), expressions change the body inside their
// spans only, continuously, and the ECS system shows the expressed strain.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include <tutti/components/body_motion.hpp>
#include <tutti/components/breath.hpp>
#include "ensemble_fixture.hpp"
#include <tutti/ensemble_variation/ensemble_variation_system.hpp>
#include <tutti/ensemble_variation/evaluate_body_motion.hpp>

namespace tutti::ensemble_variation {
namespace {

using test::four_four;
using test::player;

// Times (sampled every millisecond in [from_s, to_s)) where the bell is at a local maximum
// above half of `floor_rad`: one per cue gesture.
std::vector<double> bell_peaks(const PerformerMotionPlan& p, double from_s, double to_s,
                               double floor_rad) {
  std::vector<double> peaks;
  const int from = static_cast<int>(std::lround(from_s * 1000.0));
  const int to = static_cast<int>(std::lround(to_s * 1000.0));
  float before = evaluate_body_motion(p, (from - 1) / 1000.0).bell_lift_rad;
  float now = evaluate_body_motion(p, from / 1000.0).bell_lift_rad;
  for (int ms = from; ms < to; ++ms) {
    const float next = evaluate_body_motion(p, (ms + 1) / 1000.0).bell_lift_rad;
    if (now > 0.5 * floor_rad && now >= before && now > next) peaks.push_back(ms / 1000.0);
    before = now;
    now = next;
  }
  return peaks;
}

std::vector<PerformerInput> lead_and_follower(const music::Score& score,
                                              const test::Breaths& none) {
  std::vector<PerformerInput> inputs = {player(score, none, 1, true),
                                        player(score, none, 2, false)};
  inputs[0].params.cue_strength = 1.0;
  inputs[1].params.cue_strength = 1.0;
  return inputs;
}

TEST(Cues, AutomaticIsOneCueAtTheFirstEntrance) {
  const music::Score score = four_four();
  const test::Breaths none;
  const auto inputs = lead_and_follower(score, none);
  auto automatic = plan_ensemble(inputs);
  ASSERT_TRUE(automatic);
  ASSERT_EQ(automatic->cue_entrances_s, std::vector<double>{2.0});
  for (const PerformerMotionPlan& p : automatic->performers) ASSERT_EQ(p.cues.size(), 1u);
  const CueMotion& cue = automatic->performers[0].cues[0];
  EXPECT_DOUBLE_EQ(cue.start_s, 1.5);
  EXPECT_DOUBLE_EQ(cue.lift_s, 1.75);
  EXPECT_DOUBLE_EQ(cue.dip_s, 2.0);
  EXPECT_DOUBLE_EQ(cue.end_s, 2.25);
  EXPECT_EQ(bell_peaks(automatic->performers[0], 0.0, 10.0, 0.14), std::vector<double>{1.75});

  // The same as asking for exactly that entrance.
  EnsembleOptions options;
  options.cues_s = std::vector<double>{2.0};
  auto explicit_one = plan_ensemble(inputs, options);
  ASSERT_TRUE(explicit_one);
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const CueMotion& a = automatic->performers[i].cues[0];
    const CueMotion& b = explicit_one->performers[i].cues.at(0);
    EXPECT_EQ(a.start_s, b.start_s);
    EXPECT_EQ(a.end_s, b.end_s);
    EXPECT_EQ(a.strength, b.strength);
  }
}

TEST(Cues, AnExplicitListGivesEveryCueAndTheFollowersAnswerEach) {
  const music::Score score = four_four();
  const test::Breaths none;
  EnsembleOptions options;
  options.cues_s = std::vector<double>{6.0, 2.0};  // any order
  auto plan = plan_ensemble(lead_and_follower(score, none), options);
  ASSERT_TRUE(plan);
  EXPECT_EQ(plan->cue_entrances_s, (std::vector<double>{2.0, 6.0}));
  EXPECT_EQ(plan->dropped_cues, 0);
  const PerformerMotionPlan& lead = plan->performers[0];
  const PerformerMotionPlan& follower = plan->performers[1];
  ASSERT_EQ(lead.cues.size(), 2u);
  ASSERT_EQ(follower.cues.size(), 2u);
  // Two bell lifts, each half a beat into the beat before its entrance.
  const std::vector<double> lifts = bell_peaks(lead, 0.0, 10.0, 0.14);
  ASSERT_EQ(lifts.size(), 2u);
  EXPECT_NEAR(lifts[0], 1.75, 0.002);
  EXPECT_NEAR(lifts[1], 5.75, 0.002);
  // The dip (knees most flexed) on each entrance.
  EXPECT_NEAR(evaluate_body_motion(lead, 6.0).knee_flex_m, 0.03, 1e-4);
  EXPECT_EQ(evaluate_body_motion(lead, 4.0).bell_lift_rad, 0.0f) << "still between the cues";
  // The follower answers both, 60..140 ms late, smaller.
  const std::vector<double> answers = bell_peaks(follower, 0.0, 10.0, 0.14 / 3.0);
  ASSERT_EQ(answers.size(), 2u);
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_GT(answers[c] - lifts[c], 0.059) << c;
    EXPECT_LT(answers[c] - lifts[c], 0.141) << c;
    EXPECT_LT(evaluate_body_motion(follower, answers[c]).bell_lift_rad,
              0.5 * evaluate_body_motion(lead, lifts[c]).bell_lift_rad);
  }
}

TEST(Cues, AnEmptyListOrNoLeadMeansNoCue) {
  const music::Score score = four_four();
  const test::Breaths none;
  EnsembleOptions empty;
  empty.cues_s = std::vector<double>{};
  auto plan = plan_ensemble(lead_and_follower(score, none), empty);
  ASSERT_TRUE(plan);
  EXPECT_TRUE(plan->cue_entrances_s.empty());
  for (const PerformerMotionPlan& p : plan->performers) {
    EXPECT_TRUE(p.cues.empty());
    for (int ms = 0; ms < 10000; ms += 5) {
      const components::BodyMotion m = evaluate_body_motion(p, ms / 1000.0);
      EXPECT_EQ(m.bell_lift_rad, 0.0f);
      EXPECT_EQ(m.knee_flex_m, 0.0f);
    }
  }
  EnsembleOptions two;
  two.cues_s = std::vector<double>{2.0, 6.0};
  auto leaderless =
      plan_ensemble({player(score, none, 1, false), player(score, none, 2, false)}, two);
  ASSERT_TRUE(leaderless);
  EXPECT_EQ(leaderless->lead, -1);
  for (const PerformerMotionPlan& p : leaderless->performers) EXPECT_TRUE(p.cues.empty());
}

TEST(Cues, ACueTooCloseToThePreviousOneIsDropped) {
  const music::Score score = four_four();
  const test::Breaths none;
  EnsembleOptions options;
  // 2.2 would lift at 1.7 s, before the cue at 2.0 settles (2.25 s); 2.75 starts exactly then.
  options.cues_s =
      std::vector<double>{2.0, 2.2, 2.75, 2.75, std::numeric_limits<double>::quiet_NaN()};
  auto plan = plan_ensemble(lead_and_follower(score, none), options);
  ASSERT_TRUE(plan);
  EXPECT_EQ(plan->cue_entrances_s, (std::vector<double>{2.0, 2.75}));
  EXPECT_EQ(plan->dropped_cues, 3);
  for (const PerformerMotionPlan& p : plan->performers) {
    ASSERT_EQ(p.cues.size(), 2u);
    EXPECT_LE(p.cues[0].end_s, p.cues[1].start_s);
  }
}

// A player with the given spans, and the same player without (seed 7, lead, a breath at 11 s).
struct Pair {
  PerformerMotionPlan with;
  PerformerMotionPlan without;
};

Pair with_and_without(const std::vector<ExpressionSpan>& spans) {
  const music::Score score = four_four();
  const test::Breaths breath = test::breaths({{11.0, 11.2, 11.6}, {21.0, 21.3, 21.8}});
  PerformerInput in = player(score, breath, 7, true);
  auto without = plan_ensemble({in});
  in.expressions = spans;
  auto with = plan_ensemble({in});
  EXPECT_TRUE(with && without);
  return {with->performers[0], without->performers[0]};
}

ExpressionSpan span(ExpressionKind kind, double start_s, double end_s, double amount) {
  ExpressionSpan s;
  s.kind = kind;
  s.start_s = start_s;
  s.end_s = end_s;
  s.amount = amount;
  return s;
}

TEST(Expressions, StrainRaisesShouldersAndShownStrainAndRelaxedLowersThem) {
  const Pair p = with_and_without({span(ExpressionKind::strain, 10.0, 14.0, 0.8),
                                   span(ExpressionKind::relaxed, 20.0, 24.0, 1.0)});
  // Inside the strain span (the breath at 11 s included): shoulders up, at least the span's
  // strain shown, less sway, the bell higher, the breathing chest tighter.
  for (double t : {10.5, 11.4, 12.0, 13.5}) {
    const components::BodyMotion a = evaluate_body_motion(p.with, t, 0.1);
    const components::BodyMotion b = evaluate_body_motion(p.without, t, 0.1);
    EXPECT_GT(a.shoulder_lift_m, b.shoulder_lift_m + 0.009f) << t;
    EXPECT_GE(a.strain, 0.8 - 1e-12) << t;
    EXPECT_EQ(b.strain, 0.1) << t;
    EXPECT_LE(std::abs(a.sway_rad), 0.53f * std::abs(b.sway_rad) + 1e-7f) << t;
    EXPECT_GT(a.bell_lift_rad, b.bell_lift_rad + 0.035f) << t;
    EXPECT_LE(a.lean_back_rad, b.lean_back_rad) << t;
  }
  EXPECT_LT(evaluate_body_motion(p.with, 11.6).lean_back_rad,
            0.7f * evaluate_body_motion(p.without, 11.6).lean_back_rad);
  // A strain above the span's amount stays.
  EXPECT_EQ(evaluate_body_motion(p.with, 12.0, 0.95).strain, 0.95);
  // Inside the relaxed span: shoulders down, the strain gone, a wider sway.
  for (double t : {20.5, 21.5, 22.0, 23.5}) {
    const components::BodyMotion a = evaluate_body_motion(p.with, t, 0.5);
    const components::BodyMotion b = evaluate_body_motion(p.without, t, 0.5);
    EXPECT_LT(a.shoulder_lift_m, b.shoulder_lift_m - 0.009f) << t;
    EXPECT_EQ(a.strain, 0.0) << t;
    EXPECT_GE(std::abs(a.sway_rad), 1.55f * std::abs(b.sway_rad)) << t;
  }
  // Half the amount: half the effect on the shown strain.
  const Pair half = with_and_without({span(ExpressionKind::relaxed, 20.0, 24.0, 0.5)});
  EXPECT_DOUBLE_EQ(evaluate_body_motion(half.with, 22.0, 0.6).strain, 0.3);
}

TEST(Expressions, TheMotionIsContinuousAtTheSpanEdges) {
  // Two long spans back to back, and one shorter than two ramps.
  const Pair p = with_and_without({span(ExpressionKind::strain, 10.0, 14.0, 1.0),
                                   span(ExpressionKind::relaxed, 14.0, 18.0, 1.0),
                                   span(ExpressionKind::strain, 20.0, 20.2, 1.0)});
  // At the peak of the short span the full amount shows (its ramps are 0.1 s).
  EXPECT_DOUBLE_EQ(evaluate_body_motion(p.with, 20.1).strain, 1.0);
  // Every millisecond, what the expressions add changes by little: the steepest ramp (the short
  // span's, minimum-jerk over 0.1 s) moves 1.875 / 100 = 0.019 of its full effect per ms.
  const auto diff = [&](double t) {
    const components::BodyMotion a = evaluate_body_motion(p.with, t, 0.2);
    const components::BodyMotion b = evaluate_body_motion(p.without, t, 0.2);
    return std::array<double, 6>{a.strain - b.strain,
                                 a.shoulder_lift_m - b.shoulder_lift_m,
                                 a.sway_rad - b.sway_rad,
                                 a.twist_rad - b.twist_rad,
                                 a.bell_lift_rad - b.bell_lift_rad,
                                 a.lean_back_rad - b.lean_back_rad};
  };
  const double limits[6] = {0.02, 3e-4, 2e-3, 2e-3, 2e-3, 2e-3};
  std::array<double, 6> before = diff(9.5);
  for (int ms = 9501; ms < 21000; ++ms) {
    const std::array<double, 6> now = diff(ms / 1000.0);
    for (std::size_t k = 0; k < 6; ++k) {
      ASSERT_LE(std::abs(now[k] - before[k]), limits[k]) << "field " << k << " at " << ms << " ms";
    }
    before = now;
  }
  // And at the edges themselves nothing shows yet.
  for (double t : {10.0, 14.0, 18.0, 20.0, 20.2}) {
    const components::BodyMotion a = evaluate_body_motion(p.with, t, 0.2);
    const components::BodyMotion b = evaluate_body_motion(p.without, t, 0.2);
    EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << t;
  }
}

TEST(Expressions, OutsideEverySpanTheMotionIsBitIdentical) {
  const Pair p = with_and_without({span(ExpressionKind::strain, 10.0, 14.0, 1.0),
                                   span(ExpressionKind::relaxed, 20.0, 24.0, 0.7),
                                   span(ExpressionKind::strain, 3.0, 2.0, 1.0)});  // empty: dropped
  EXPECT_EQ(p.with.expressions.size(), 2u);
  int compared = 0;
  for (int ms = 0; ms < 32000; ms += 3) {
    const double t = ms / 1000.0;
    if ((t > 10.0 && t < 14.0) || (t > 20.0 && t < 24.0)) continue;
    const components::BodyMotion a = evaluate_body_motion(p.with, t, 0.4);
    const components::BodyMotion b = evaluate_body_motion(p.without, t, 0.4);
    ASSERT_EQ(std::memcmp(&a, &b, sizeof a), 0) << t;
    ++compared;
  }
  EXPECT_GT(compared, 8000);
}

TEST(Expressions, OverlappingSpansAreMadeDisjointInStartOrder) {
  const Pair p = with_and_without({span(ExpressionKind::relaxed, 12.0, 16.0, 2.0),
                                   span(ExpressionKind::strain, 10.0, 14.0, 0.5),
                                   span(ExpressionKind::strain, 11.0, 13.0, 1.0)});
  ASSERT_EQ(p.with.expressions.size(), 2u);
  EXPECT_EQ(p.with.expressions[0].kind, ExpressionKind::strain);
  EXPECT_EQ(p.with.expressions[0].start_s, 10.0);
  EXPECT_EQ(p.with.expressions[1].kind, ExpressionKind::relaxed);
  EXPECT_EQ(p.with.expressions[1].start_s, 14.0);
  EXPECT_EQ(p.with.expressions[1].amount, 1.0);  // clamped
}

TEST(Expressions, TheSystemShowsTheExpressedStrainOfTheBreath) {
  const music::Score score = four_four();
  const test::Breaths none;
  PerformerInput in = player(score, none, 7, true);
  in.expressions = {span(ExpressionKind::strain, 10.0, 14.0, 0.8)};
  auto plan = plan_ensemble({in});
  ASSERT_TRUE(plan);
  ecs::World world;
  const ecs::Entity performer = world.create();
  world.add<EnsembleMotionHandle>(
      performer, EnsembleMotionHandle{std::make_shared<const EnsemblePlan>(std::move(*plan)), 0});
  world.add<components::BodyMotion>(performer);
  components::Breath breath;
  breath.strain = 0.3;
  world.add<components::Breath>(performer, breath);
  ecs::FrameTime frame;
  frame.t_s = 12.0;
  ensemble_variation_system(world, frame);
  EXPECT_DOUBLE_EQ(world.try_get<components::BodyMotion>(performer)->strain, 0.8);
  frame.t_s = 5.0;
  ensemble_variation_system(world, frame);
  EXPECT_EQ(world.try_get<components::BodyMotion>(performer)->strain, 0.3);
}

}  // namespace
}  // namespace tutti::ensemble_variation
