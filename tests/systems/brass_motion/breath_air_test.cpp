// SPDX-License-Identifier: MIT
// The air model: drain by loudness and register, strain, catch-breaths, determinism, and the
// continuity of evaluate_breath.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "breath_fixture.hpp"

namespace tutti::brass_motion {

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::Instrument;
using brass_model::LineNote;

namespace {

using test::fixed_params;
using test::line_of;
using test::note_q;
using test::score_at;

// Air left after one note of 2 s (quarters 0..4 at 120 bpm); the breath before the entrance
// fills the lungs first.
double air_after_one_note(int written, int velocity, const Instrument* instrument) {
  const music::Score score = score_at(120);
  BrassLine line = line_of({note_q(score, 0, 4, written, velocity)});
  line.instrument = instrument;
  const BreathPlan plan = plan_breaths(line, score, fixed_params());
  EXPECT_DOUBLE_EQ(evaluate_breath(plan, 0.0).air, 1.0);
  return evaluate_breath(plan, 2.0).air;
}

TEST(BreathAir, DrainsFasterWhenLoudOrHigh) {
  Instrument trumpet;
  trumpet.id = "test_trumpet";
  trumpet.lowest_written = 54;
  trumpet.highest_written = 86;  // middle: 70
  // mf in the middle of the range: 2 s of the 8 s capacity.
  EXPECT_NEAR(air_after_one_note(70, 80, &trumpet), 1.0 - 2.0 / 8.0, 1e-12);
  // ff at the top: 1.8 × 1.4 times as fast.
  EXPECT_NEAR(air_after_one_note(86, 127, &trumpet), 1.0 - 2.0 * 1.8 * 1.4 / 8.0, 1e-12);
  // pp at the bottom: 0.6 × 0.85.
  EXPECT_NEAR(air_after_one_note(54, 1, &trumpet), 1.0 - 2.0 * 0.6 * 0.85 / 8.0, 1e-12);
  // Between the anchors, linear: velocity 40, a quarter of the way up the range.
  const double loudness = 0.6 + 0.4 * (40.0 - 1.0) / (80.0 - 1.0);
  const double reg = 0.85 + 0.15 * 0.5;
  EXPECT_NEAR(air_after_one_note(62, 40, &trumpet), 1.0 - 2.0 * loudness * reg / 8.0, 1e-12);
  // Without an instrument the line's own range is used: one pitch = the middle.
  EXPECT_NEAR(air_after_one_note(86, 80, nullptr), 0.75, 1e-12);
}

// 24 quarters at 120 bpm without a rest (12 s, half as long again as the air lasts at mf):
// quarters, with half notes on quarters 4 (downbeat), 10 (third beat) and 16 (downbeat).
BrassLine long_phrase(const music::Score& score) {
  std::vector<LineNote> notes;
  for (double q = 0; q < 24;) {
    const bool half = q == 4 || q == 10 || q == 16;
    notes.push_back(note_q(score, q, q + (half ? 2 : 1)));
    q += half ? 2 : 1;
  }
  return line_of(notes);
}

TEST(BreathAir, LongPhraseGetsCatchBreathsAndEndsStrained) {
  const music::Score score = score_at(120);
  const BrassLine line = long_phrase(score);
  ASSERT_EQ(line.notes.size(), 21u);
  const BreathPlan plan = plan_breaths(line, score, fixed_params());

  // Full at 0 s, air drains at 1/8 per second and would fall below the 0.1 reserve at 7.2 s.
  // Of the places where the air is below 0.5 (after 4 s), the end of the half note on quarter
  // 10 (note 9) scores best: 2 beats × 1.25 (on a beat) with no strain yet; the downbeat
  // quarter at 12 would score 1.5 × (1 - strain). The note is cut by catch_inhale_s.
  ASSERT_EQ(plan.events.size(), 3u);
  EXPECT_EQ(plan.catch_breaths, 2);
  EXPECT_EQ(plan.out_of_air, 0);
  const BreathEvent& first = plan.events[1];
  EXPECT_EQ(first.kind, BreathKind::catch_breath);
  EXPECT_EQ(first.before_note, 10);
  EXPECT_NEAR(first.start_s, 5.75, 1e-9);
  EXPECT_NEAR(first.prepare_start_s, 5.75, 1e-9);
  EXPECT_NEAR(first.end_s, 6.0, 1e-9);
  EXPECT_NEAR(first.rest_beats, 0.0, 1e-12);
  EXPECT_NEAR(first.depth, 1.0 - 5.75 / 8.0 + 0.25 * 1.25, 1e-9);
  // Then the half note on the downbeat of bar 5 (quarters 16..18, note 14): 2 beats × 1.5.
  const BreathEvent& second = plan.events[2];
  EXPECT_EQ(second.kind, BreathKind::catch_breath);
  EXPECT_EQ(second.before_note, 15);
  EXPECT_NEAR(second.start_s, 8.75, 1e-9);
  EXPECT_NEAR(second.end_s, 9.0, 1e-9);
  EXPECT_NEAR(second.depth, first.depth - 2.75 / 8.0 + 0.25 * 1.25, 1e-9);

  ASSERT_EQ(plan.shortened.size(), 2u);
  EXPECT_EQ(plan.shortened[0].note, 9);
  EXPECT_NEAR(plan.shortened[0].offset_s, 5.75, 1e-9);
  EXPECT_NEAR(plan.shortened[0].offset_beats, 11.5, 1e-9);
  EXPECT_EQ(plan.shortened[1].note, 14);
  EXPECT_NEAR(plan.shortened[1].offset_s, 8.75, 1e-9);

  // During the catch-breath: inhaling, air rising.
  const BreathState during = evaluate_breath(plan, 5.875);
  EXPECT_EQ(during.breath_index, 1);
  EXPECT_NEAR(during.inhale, 1.0, 1e-9);
  EXPECT_GT(during.air, evaluate_breath(plan, 5.75).air);
  EXPECT_LT(during.air, evaluate_breath(plan, 6.0).air);

  // The phrase ends at 12 s with 0.1875 left: no strain until the air passes 0.25 (11.5 s),
  // then rising to the end.
  EXPECT_NEAR(evaluate_breath(plan, 12.0).air, second.depth - 3.0 / 8.0, 1e-9);
  EXPECT_EQ(evaluate_breath(plan, 11.5).strain, 0.0);
  double previous = 0.0;
  for (double t = 11.55; t <= 12.0; t += 0.05) {
    const double strain = evaluate_breath(plan, t).strain;
    EXPECT_GT(strain, previous) << "t = " << t;
    previous = strain;
  }
  EXPECT_NEAR(plan.min_air, 0.1875, 1e-9);
  EXPECT_NEAR(plan.max_strain, strain_at_air(0.1875, 0.25), 1e-12);
  EXPECT_NEAR(evaluate_breath(plan, 12.0).strain, plan.max_strain, 1e-9);

  test::expect_continuous(plan, -2.0, 13.0);
}

TEST(BreathAir, PhraseWithNowhereToBreatheRunsOutAndStrainsFully) {
  // Sixteenths at 120 bpm (0.125 s) for 12 s: a catch-breath would need at least 0.12 s, and
  // only 0.05 s (catch_max_cut) of a sixteenth may be cut.
  const music::Score score = score_at(120);
  std::vector<LineNote> notes;
  for (int i = 0; i < 96; ++i) notes.push_back(note_q(score, 0.25 * i, 0.25 * (i + 1)));
  const BreathPlan plan = plan_breaths(line_of(notes), score, fixed_params());
  EXPECT_EQ(plan.events.size(), 1u);
  EXPECT_EQ(plan.catch_breaths, 0);
  EXPECT_EQ(plan.out_of_air, 1);
  EXPECT_EQ(plan.min_air, 0.0);
  EXPECT_EQ(plan.max_strain, 1.0);
  double previous = -1.0;
  for (double t = 0.0; t <= 12.0; t += 0.01) {
    const BreathState s = evaluate_breath(plan, t);
    EXPECT_GE(s.strain, previous) << "t = " << t;
    EXPECT_GE(s.air, 0.0);
    previous = s.strain;
  }
  EXPECT_NEAR(evaluate_breath(plan, 7.0).air, 1.0 / 8.0, 1e-9);
  EXPECT_NEAR(evaluate_breath(plan, 8.0).air, 0.0, 1e-12);
  EXPECT_EQ(evaluate_breath(plan, 8.2).air, 0.0);
  EXPECT_EQ(evaluate_breath(plan, 10.0).strain, 1.0);

  // A sixteenth rest (a quarter of a beat: no rule breath) at quarter 10 (5 s, air 0.375) is
  // the one place a catch-breath fits: the rest (0.125 s) plus 0.05 s of the note before.
  notes.erase(notes.begin() + 40);
  const BreathPlan caught = plan_breaths(line_of(notes), score, fixed_params());
  ASSERT_EQ(caught.events.size(), 2u);
  EXPECT_EQ(caught.events[1].kind, BreathKind::catch_breath);
  EXPECT_EQ(caught.events[1].before_note, 40);
  EXPECT_NEAR(caught.events[1].start_s, 5.0 - 0.05, 1e-9);
  EXPECT_NEAR(caught.events[1].end_s, 5.125, 1e-9);
  EXPECT_NEAR(caught.events[1].rest_beats, 0.25, 1e-9);
  ASSERT_EQ(caught.shortened.size(), 1u);
  EXPECT_EQ(caught.shortened[0].note, 39);
  EXPECT_NEAR(caught.shortened[0].offset_s, 4.95, 1e-9);
  EXPECT_NEAR(caught.events[1].depth, 1.0 - 4.95 / 8.0 + 0.175 * 1.25, 1e-9);
  // 0.175 s of inhale (+0.22) is not enough for the rest of the phrase: it still runs out,
  // later (at 5.125 + 0.6 × 8 = 9.925 s).
  EXPECT_EQ(caught.out_of_air, 1);
  EXPECT_GT(evaluate_breath(caught, 9.9).air, 0.0);
  EXPECT_EQ(evaluate_breath(caught, 9.95).air, 0.0);
}

void expect_same(const BreathPlan& a, const BreathPlan& b) {
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    EXPECT_EQ(a.events[i].kind, b.events[i].kind);
    EXPECT_EQ(a.events[i].prepare_start_s, b.events[i].prepare_start_s);
    EXPECT_EQ(a.events[i].start_s, b.events[i].start_s);
    EXPECT_EQ(a.events[i].end_s, b.events[i].end_s);
    EXPECT_EQ(a.events[i].depth, b.events[i].depth);
    EXPECT_EQ(a.events[i].before_note, b.events[i].before_note);
  }
  ASSERT_EQ(a.air.size(), b.air.size());
  for (std::size_t i = 0; i < a.air.size(); ++i) {
    EXPECT_EQ(a.air[i].start_s, b.air[i].start_s);
    EXPECT_EQ(a.air[i].end_s, b.air[i].end_s);
    EXPECT_EQ(a.air[i].from, b.air[i].from);
    EXPECT_EQ(a.air[i].to, b.air[i].to);
  }
  ASSERT_EQ(a.shortened.size(), b.shortened.size());
  for (std::size_t i = 0; i < a.shortened.size(); ++i) {
    EXPECT_EQ(a.shortened[i].note, b.shortened[i].note);
    EXPECT_EQ(a.shortened[i].offset_s, b.shortened[i].offset_s);
  }
}

TEST(BreathAir, PlanningAndEvaluationAreDeterministic) {
  const music::Score score = score_at(96);
  BrassLine line = long_phrase(score);
  line.notes.push_back(note_q(score, 27, 29));  // after a prepared breath
  line.notes.push_back(note_q(score, 29.75, 31));
  const BreathPlan a = plan_breaths(line, score, fixed_params());
  const BreathPlan b = plan_breaths(line, score, fixed_params());
  expect_same(a, b);
  EXPECT_GE(a.events.size(), 4u);

  // Same t, same state, whatever was evaluated before (seek anywhere).
  std::vector<double> times;
  for (int i = -200; i < 2400; ++i) times.push_back(i / 100.0);
  std::vector<BreathState> in_order;
  for (double t : times) in_order.push_back(evaluate_breath(a, t));
  std::vector<std::size_t> order(times.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  for (std::size_t i : order) {
    const BreathState s = evaluate_breath(a, times[i]);
    EXPECT_EQ(s.air, in_order[i].air);
    EXPECT_EQ(s.inhale, in_order[i].inhale);
    EXPECT_EQ(s.preparing, in_order[i].preparing);
    EXPECT_EQ(s.strain, in_order[i].strain);
    EXPECT_EQ(s.breath_index, in_order[i].breath_index);
  }
}

TEST(BreathAir, EvaluationIsContinuousAcrossEveryBoundary) {
  const music::Score score = score_at(120);
  // Rests of every class, a long phrase, an unplayable note.
  std::vector<LineNote> notes = {note_q(score, 2, 4), note_q(score, 4.75, 6), note_q(score, 7.5, 9),
                                 note_q(score, 12, 14), note_q(score, 14, 16, 72, 80, false)};
  for (double q = 16; q < 40; q += 1) notes.push_back(note_q(score, q, q + 1, 74, 110));
  const BreathPlan plan = plan_breaths(line_of(notes), score, fixed_params());
  ASSERT_GE(plan.events.size(), 5u);
  test::expect_continuous(plan, -3.0, 22.0);

  // At every event and segment edge, the two sides agree; inhale and preparing are 0 there.
  std::vector<double> edges;
  for (const BreathEvent& e : plan.events) {
    edges.insert(edges.end(), {e.prepare_start_s, e.start_s, e.end_s});
  }
  for (const AirSegment& s : plan.air) edges.insert(edges.end(), {s.start_s, s.end_s});
  for (double edge : edges) {
    const BreathState left = evaluate_breath(plan, edge - 1e-9);
    const BreathState right = evaluate_breath(plan, edge + 1e-9);
    EXPECT_NEAR(left.air, right.air, 1e-7) << "edge " << edge;
    EXPECT_NEAR(left.inhale, right.inhale, 1e-7) << "edge " << edge;
    EXPECT_NEAR(left.preparing, right.preparing, 1e-7) << "edge " << edge;
    EXPECT_NEAR(left.strain, right.strain, 1e-7) << "edge " << edge;
    EXPECT_NEAR(evaluate_breath(plan, edge).inhale, 0.0, 1e-9);
  }
  // Events are in time order and do not overlap; so are the air segments.
  for (std::size_t i = 1; i < plan.events.size(); ++i) {
    EXPECT_GE(plan.events[i].prepare_start_s, plan.events[i - 1].end_s);
  }
  for (std::size_t i = 1; i < plan.air.size(); ++i) {
    EXPECT_GE(plan.air[i].start_s, plan.air[i - 1].end_s);
    EXPECT_EQ(plan.air[i].from, plan.air[i - 1].to);
  }
  // NaN and infinities are handled.
  EXPECT_EQ(evaluate_breath(plan, std::nan("")).breath_index, -1);
  EXPECT_EQ(evaluate_breath(plan, 1e300).breath_index, static_cast<int>(plan.events.size()) - 1);
}

}  // namespace
}  // namespace tutti::brass_motion
