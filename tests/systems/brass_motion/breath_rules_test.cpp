// SPDX-License-Identifier: MIT
// Horii's breath rules, measured in beats of the meter and converted to seconds through the
// tempo map: two tempi, tempo changes inside a rest, 6/8, the first entrance, unplayable notes.
#include <gtest/gtest.h>

#include "breath_fixture.hpp"

namespace tutti::brass_motion {

// The brass model's names used here (systems/brass_model).
using brass_model::LineNote;

namespace {

using test::fixed_params;
using test::line_of;
using test::note_q;
using test::score_at;

// Two half notes with `rest_q` quarters of rest between them; returns the plan.
BreathPlan two_notes(const music::Score& score, double rest_q) {
  return plan_breaths(line_of({note_q(score, 0, 2), note_q(score, 2 + rest_q, 4 + rest_q)}), score,
                      fixed_params());
}

struct Expected {
  double rest_q;
  int events;  // including the breath before the first entrance
  BreathKind kind;
  double window_start_s, start_s, prepare_start_s, end_s;
};

void expect_rest_breath(const music::Score& score, const Expected& x) {
  SCOPED_TRACE("rest of " + std::to_string(x.rest_q) + " beats at " +
               std::to_string(score.tempo_map.bpm_at(0)) + " bpm");
  const BreathPlan plan = two_notes(score, x.rest_q);
  ASSERT_EQ(static_cast<int>(plan.events.size()), x.events);
  EXPECT_EQ(plan.events[0].kind, BreathKind::before_entrance);
  if (x.events < 2) return;
  const BreathEvent& e = plan.events[1];
  EXPECT_EQ(e.kind, x.kind);
  EXPECT_EQ(e.before_note, 1);
  EXPECT_NEAR(e.rest_beats, x.rest_q, 1e-9);
  EXPECT_NEAR(e.window_start_s, x.window_start_s, 1e-9);
  EXPECT_NEAR(e.start_s, x.start_s, 1e-9);
  EXPECT_NEAR(e.prepare_start_s, x.prepare_start_s, 1e-9);
  EXPECT_NEAR(e.end_s, x.end_s, 1e-9);
  EXPECT_GT(e.depth, 0.0);
  EXPECT_LE(e.depth, 1.0);
}

TEST(BreathRules, SameRestsInBeatsAt60And120Bpm) {
  // At 120 bpm a quarter is 0.5 s; the first note ends at 1.0 s.
  const music::Score fast = score_at(120);
  expect_rest_breath(fast, {0.25, 1, BreathKind::in_rest, 0, 0, 0, 0});  // < 0.5 beat: none
  expect_rest_breath(fast, {0.75, 2, BreathKind::in_rest, 1.0, 1.0, 1.0, 1.375});
  expect_rest_breath(fast, {1.5, 2, BreathKind::last_beat, 1.25, 1.25, 1.25, 1.75});
  // Last two beats = 1.0 s, all of it inhale (inhale_max_s = 1); the preparation would start
  // 0.6 s earlier but the rest only began at 1.0 s.
  expect_rest_breath(fast, {3, 2, BreathKind::prepared, 1.5, 1.5, 1.0, 2.5});

  // At 60 bpm everything takes twice as long, except that an inhale lasts at most 1 s.
  const music::Score slow = score_at(60);
  expect_rest_breath(slow, {0.25, 1, BreathKind::in_rest, 0, 0, 0, 0});
  expect_rest_breath(slow, {0.75, 2, BreathKind::in_rest, 2.0, 2.0, 2.0, 2.75});
  expect_rest_breath(slow, {1.5, 2, BreathKind::last_beat, 2.5, 2.5, 2.5, 3.5});
  expect_rest_breath(slow, {3, 2, BreathKind::prepared, 3.0, 4.0, 3.4, 5.0});

  // The thresholds themselves: exactly 0.5, 1 and 2 beats fall in the upper class.
  EXPECT_EQ(two_notes(fast, 0.5).events.at(1).kind, BreathKind::in_rest);
  EXPECT_EQ(two_notes(fast, 1.0).events.at(1).kind, BreathKind::last_beat);
  EXPECT_EQ(two_notes(fast, 2.0).events.at(1).kind, BreathKind::prepared);
  EXPECT_EQ(two_notes(fast, 0.499).events.size(), 1u);
}

TEST(BreathRules, RestSpanningATempoChangeIsTimedExactly) {
  // 120 bpm, then 60 bpm from quarter 5 on. The rest runs from quarter 2 to 6 (4 beats): the
  // last two beats are quarters 4..6 = 0.5 s at 120 + 1 s at 60 = 2.0 .. 3.5 s.
  music::Score score = score_at(120);
  score.tempo_map.set_tempo(test::tick_of(5), 1'000'000.0);
  BreathPlan plan = two_notes(score, 4);
  ASSERT_EQ(plan.events.size(), 2u);
  const BreathEvent& prepared = plan.events[1];
  EXPECT_EQ(prepared.kind, BreathKind::prepared);
  EXPECT_NEAR(prepared.window_start_s, 2.0, 1e-9);
  EXPECT_NEAR(prepared.end_s, 3.5, 1e-9);
  EXPECT_NEAR(prepared.start_s, 2.5, 1e-9);          // the last inhale_max_s = 1 s
  EXPECT_NEAR(prepared.prepare_start_s, 1.9, 1e-9);  // prepare_s = 0.6 before

  // A rest of 1.5 beats (quarters 2..3.5) with 60 bpm from quarter 3: the last beat is
  // quarters 2.5..3.5 = 0.25 s at 120 + 0.5 s at 60 = 1.25 .. 2.0 s (neither 0.5 s nor 1 s,
  // which either tempo alone would give).
  score = score_at(120);
  score.tempo_map.set_tempo(test::tick_of(3), 1'000'000.0);
  plan = two_notes(score, 1.5);
  ASSERT_EQ(plan.events.size(), 2u);
  EXPECT_EQ(plan.events[1].kind, BreathKind::last_beat);
  EXPECT_NEAR(plan.events[1].window_start_s, 1.25, 1e-9);
  EXPECT_NEAR(plan.events[1].start_s, 1.25, 1e-9);
  EXPECT_NEAR(plan.events[1].end_s, 2.0, 1e-9);

  // The same rest at a steady 120 bpm, for contrast.
  plan = two_notes(score_at(120), 1.5);
  EXPECT_NEAR(plan.events[1].end_s - plan.events[1].start_s, 0.5, 1e-9);
}

TEST(BreathRules, BreathBeforeTheFirstEntrance) {
  // Entrance after a bar's rest at 60 bpm: preparation, then the last inhale_max_s of the last
  // two beats.
  const music::Score slow = score_at(60);
  BreathPlan plan = plan_breaths(line_of({note_q(slow, 4, 6)}), slow, fixed_params());
  ASSERT_EQ(plan.events.size(), 1u);
  BreathEvent e = plan.events[0];
  EXPECT_EQ(e.kind, BreathKind::before_entrance);
  EXPECT_EQ(e.before_note, 0);
  EXPECT_NEAR(e.window_start_s, 2.0, 1e-9);
  EXPECT_NEAR(e.start_s, 3.0, 1e-9);
  EXPECT_NEAR(e.prepare_start_s, 2.4, 1e-9);
  EXPECT_NEAR(e.end_s, 4.0, 1e-9);
  EXPECT_NEAR(e.rest_beats, 4.0, 1e-9);
  // From resting_air 0.45, 1 s of inhale at 1.25/s fills the lungs.
  EXPECT_DOUBLE_EQ(e.depth, 1.0);

  // Entrance on the downbeat at 120 bpm: the breath is taken before the music starts, in the
  // two beats before it at the opening tempo.
  const music::Score fast = score_at(120);
  plan = plan_breaths(line_of({note_q(fast, 0, 2)}), fast, fixed_params());
  ASSERT_EQ(plan.events.size(), 1u);
  e = plan.events[0];
  EXPECT_EQ(e.kind, BreathKind::before_entrance);
  EXPECT_NEAR(e.window_start_s, -1.0, 1e-9);
  EXPECT_NEAR(e.start_s, -1.0, 1e-9);
  EXPECT_NEAR(e.prepare_start_s, -1.6, 1e-9);
  EXPECT_NEAR(e.end_s, 0.0, 1e-9);

  // Before it: resting air, no event yet; at the entrance: full.
  BreathState s = evaluate_breath(plan, -5.0);
  EXPECT_EQ(s.breath_index, -1);
  EXPECT_DOUBLE_EQ(s.air, 0.45);
  EXPECT_EQ(s.inhale, 0.0);
  s = evaluate_breath(plan, -1.3);
  EXPECT_EQ(s.breath_index, 0);
  EXPECT_NEAR(s.preparing, 1.0, 1e-9);  // the middle of the preparation
  s = evaluate_breath(plan, -0.5);
  EXPECT_NEAR(s.inhale, 1.0, 1e-9);  // the middle of the inhale
  EXPECT_EQ(s.preparing, 0.0);
  EXPECT_DOUBLE_EQ(evaluate_breath(plan, 0.0).air, 1.0);
}

TEST(BreathRules, SixEightCountsDottedQuarters) {
  // In 6/8 a beat is a dotted quarter (1.5 quarters): a rest of one quarter is 2/3 of a beat
  // (breathe during the rest); in 4/4 it is a whole beat (breathe in the last beat).
  const music::Score six_eight = score_at(120, 6, 8);
  const music::Score four_four = score_at(120, 4, 4);
  auto rest_of = [](const music::Score& score, double rest_q) {
    return plan_breaths(line_of({note_q(score, 0, 3), note_q(score, 3 + rest_q, 6 + rest_q)}),
                        score, fixed_params());
  };
  BreathPlan plan = rest_of(six_eight, 1.0);
  ASSERT_EQ(plan.events.size(), 2u);
  EXPECT_EQ(plan.events[1].kind, BreathKind::in_rest);
  EXPECT_NEAR(plan.events[1].rest_beats, 2.0 / 3.0, 1e-9);
  EXPECT_EQ(rest_of(four_four, 1.0).events.at(1).kind, BreathKind::last_beat);

  // 2.25 quarters = 1.5 dotted beats: the last beat is the last dotted quarter (0.75 s).
  plan = rest_of(six_eight, 2.25);
  ASSERT_EQ(plan.events.size(), 2u);
  EXPECT_EQ(plan.events[1].kind, BreathKind::last_beat);
  EXPECT_NEAR(plan.events[1].window_start_s, 3.75 * 0.5, 1e-9);
  EXPECT_NEAR(plan.events[1].end_s, 5.25 * 0.5, 1e-9);
  EXPECT_EQ(rest_of(four_four, 2.25).events.at(1).kind, BreathKind::prepared);

  // 3 quarters = 2 dotted beats: prepared, in the last two dotted beats (all 3 quarters).
  plan = rest_of(six_eight, 3.0);
  EXPECT_EQ(plan.events.at(1).kind, BreathKind::prepared);
  EXPECT_NEAR(plan.events[1].window_start_s, 1.5, 1e-9);
}

TEST(BreathRules, MeterChangeInsideARest) {
  // 4/4 for one bar, then 6/8 from quarter 4. A rest from quarter 3 to 5.5 is 1 beat of 4/4 +
  // 1 dotted beat of 6/8 = 2 beats: prepared; its last two beats start at quarter 3.
  music::Score score = score_at(120, 4, 4);
  score.time_signatures.push_back({test::tick_of(4), 2.0, 6, 8});
  const BreathPlan plan =
      plan_breaths(line_of({note_q(score, 0, 3), note_q(score, 5.5, 7)}), score, fixed_params());
  ASSERT_EQ(plan.events.size(), 2u);
  EXPECT_EQ(plan.events[1].kind, BreathKind::prepared);
  EXPECT_NEAR(plan.events[1].rest_beats, 2.0, 1e-9);
  EXPECT_NEAR(plan.events[1].window_start_s, 1.5, 1e-9);
}

TEST(BreathRules, UnplayableNotesCountAsRest) {
  const music::Score score = score_at(120);
  std::vector<LineNote> notes = {note_q(score, 0, 2), note_q(score, 2, 5, 100),
                                 note_q(score, 5, 7)};
  // Played through: one phrase, one breath before the entrance.
  EXPECT_EQ(plan_breaths(line_of(notes), score, fixed_params()).events.size(), 1u);

  notes[1].playable = false;  // out of range: a rest of 3 beats
  const BreathPlan plan = plan_breaths(line_of(notes), score, fixed_params());
  ASSERT_EQ(plan.events.size(), 2u);
  const BreathEvent& e = plan.events[1];
  EXPECT_EQ(e.kind, BreathKind::prepared);
  EXPECT_EQ(e.before_note, 2);
  EXPECT_NEAR(e.rest_beats, 3.0, 1e-9);
  EXPECT_NEAR(e.window_start_s, 1.5, 1e-9);
  EXPECT_NEAR(e.end_s, 2.5, 1e-9);
  // No air is used while the unplayed note "sounds".
  EXPECT_DOUBLE_EQ(evaluate_breath(plan, 1.05).air, evaluate_breath(plan, 1.45).air);
  EXPECT_LT(evaluate_breath(plan, 1.0).air, evaluate_breath(plan, 0.0).air);
}

TEST(BreathRules, RestTooShortInSecondsGivesNoBreath) {
  // Half a beat at 240 bpm is 0.125 s, below inhale_min_s = 0.15.
  const music::Score score = score_at(240);
  const BreathPlan plan = two_notes(score, 0.5);
  EXPECT_EQ(plan.events.size(), 1u);
  EXPECT_EQ(plan.skipped_rests, 1);
  EXPECT_EQ(two_notes(score, 0.75).events.size(), 2u);  // 0.1875 s
}

TEST(BreathRules, EmptyLineGivesAnEmptyPlan) {
  const music::Score score = score_at(120);
  std::vector<LineNote> notes = {note_q(score, 0, 2, 72, 80, false)};
  const BreathPlan plan = plan_breaths(line_of(notes), score, fixed_params());
  EXPECT_TRUE(plan.events.empty());
  EXPECT_TRUE(plan.air.empty());
  const BreathState s = evaluate_breath(plan, 1.0);
  EXPECT_DOUBLE_EQ(s.air, 0.45);
  EXPECT_EQ(s.breath_index, -1);
}

}  // namespace
}  // namespace tutti::brass_motion
