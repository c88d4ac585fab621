// SPDX-License-Identifier: MIT
// The editor's breath marks (BreathMarks): an add mark makes a breath at a note boundary the
// rules leave alone (a catch-breath in legato, a breath in a short rest), a remove mark takes
// every breath away from its boundary, marks that refer to no note are ignored and counted, and
// the plans stay deterministic and continuous.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <tutti/brass_motion/plan_brass_player.hpp>
#include "breath_fixture.hpp"

namespace tutti::brass_motion {

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::LineNote;

namespace {

using test::fixed_params;
using test::line_of;
using test::note_q;
using test::score_at;

// `count` contiguous quarter notes from quarter 0 on (legato, no rests).
BrassLine legato_quarters(const music::Score& score, int count) {
  std::vector<LineNote> notes;
  for (int i = 0; i < count; ++i) notes.push_back(note_q(score, i, i + 1));
  return line_of(notes);
}

const BreathEvent* event_before(const BreathPlan& plan, int note) {
  for (const BreathEvent& e : plan.events) {
    if (e.before_note == note) return &e;
  }
  return nullptr;
}

void expect_same_plan(const BreathPlan& a, const BreathPlan& b) {
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    EXPECT_EQ(a.events[i].kind, b.events[i].kind) << i;
    EXPECT_EQ(a.events[i].prepare_start_s, b.events[i].prepare_start_s) << i;
    EXPECT_EQ(a.events[i].start_s, b.events[i].start_s) << i;
    EXPECT_EQ(a.events[i].end_s, b.events[i].end_s) << i;
    EXPECT_EQ(a.events[i].depth, b.events[i].depth) << i;
    EXPECT_EQ(a.events[i].before_note, b.events[i].before_note) << i;
    EXPECT_EQ(a.events[i].marked, b.events[i].marked) << i;
  }
  ASSERT_EQ(a.air.size(), b.air.size());
  for (std::size_t i = 0; i < a.air.size(); ++i) {
    EXPECT_EQ(a.air[i].start_s, b.air[i].start_s) << i;
    EXPECT_EQ(a.air[i].end_s, b.air[i].end_s) << i;
    EXPECT_EQ(a.air[i].from, b.air[i].from) << i;
    EXPECT_EQ(a.air[i].to, b.air[i].to) << i;
  }
  ASSERT_EQ(a.shortened.size(), b.shortened.size());
  for (std::size_t i = 0; i < a.shortened.size(); ++i) {
    EXPECT_EQ(a.shortened[i].note, b.shortened[i].note) << i;
    EXPECT_EQ(a.shortened[i].offset_s, b.shortened[i].offset_s) << i;
  }
  EXPECT_EQ(a.min_air, b.min_air);
  EXPECT_EQ(a.catch_breaths, b.catch_breaths);
  EXPECT_EQ(a.ignored_marks, b.ignored_marks);
}

TEST(BreathMarks, AnAddMarkInALegatoPhraseIsACatchBreathThatShortensTheNoteBefore) {
  // Eight quarters at 120 bpm (4 s): full lungs last 8 s, so the rules breathe only before the
  // entrance. The mark at 2.0 s is the boundary before note 4.
  const music::Score score = score_at(120);
  const BrassLine line = legato_quarters(score, 8);
  const BreathPlan rules = plan_breaths(line, score, fixed_params());
  ASSERT_EQ(rules.events.size(), 1u);
  EXPECT_TRUE(rules.shortened.empty());

  BreathMarks marks;
  marks.add_s = {1.99};  // a little before the onset: the first note at or after it
  const BreathPlan plan = plan_breaths(line, score, fixed_params(), marks);
  ASSERT_EQ(plan.events.size(), 2u);
  EXPECT_FALSE(plan.events[0].marked);
  const BreathEvent& e = plan.events[1];
  EXPECT_EQ(e.kind, BreathKind::catch_breath);
  EXPECT_TRUE(e.marked);
  EXPECT_EQ(e.before_note, 4);
  // The catch-breath takes catch_inhale_s, at most 40 % of the 0.5 s note: 0.2 s.
  EXPECT_NEAR(e.start_s, 1.8, 1e-9);
  EXPECT_NEAR(e.end_s, 2.0, 1e-9);
  ASSERT_EQ(plan.shortened.size(), 1u);
  EXPECT_EQ(plan.shortened[0].note, 3);
  EXPECT_NEAR(plan.shortened[0].offset_s, 1.8, 1e-9);
  EXPECT_NEAR(plan.shortened[0].offset_beats, 3.6, 1e-9);
  EXPECT_EQ(plan.ignored_marks, 0);
  // The note as played ends there, and the air model takes the breath: more air after it.
  EXPECT_NEAR(as_played(line, plan).notes[3].offset_s, 1.8, 1e-9);
  EXPECT_GT(evaluate_breath(plan, 2.0).air, evaluate_breath(plan, 1.8).air + 0.2);
  EXPECT_GT(evaluate_breath(plan, 3.9).air, evaluate_breath(rules, 3.9).air);
  EXPECT_GT(evaluate_breath(plan, 1.9).inhale, 0.9);
  test::expect_continuous(plan, -3.0, 5.0);
}

TEST(BreathMarks, AnAddMarkInAShortRestTheRulesSkipBreathes) {
  // A sixteenth rest at 120 bpm (0.125 s, a quarter of a beat): no breath by the rules, and
  // shorter than inhale_min_s, so the marked breath also takes the end of the note before.
  {
    const music::Score score = score_at(120);
    const BrassLine line = line_of({note_q(score, 0, 2), note_q(score, 2.25, 4.25)});
    ASSERT_EQ(plan_breaths(line, score, fixed_params()).events.size(), 1u);
    BreathMarks marks;
    marks.add_s = {1.05};  // inside the rest
    const BreathPlan plan = plan_breaths(line, score, fixed_params(), marks);
    ASSERT_EQ(plan.events.size(), 2u);
    const BreathEvent& e = plan.events[1];
    EXPECT_TRUE(e.marked);
    EXPECT_EQ(e.kind, BreathKind::catch_breath);
    EXPECT_EQ(e.before_note, 1);
    EXPECT_NEAR(e.start_s, 0.875, 1e-9);  // 0.125 s rest + 0.125 s of the note = catch_inhale_s
    EXPECT_NEAR(e.end_s, 1.125, 1e-9);
    ASSERT_EQ(plan.shortened.size(), 1u);
    EXPECT_EQ(plan.shortened[0].note, 0);
    EXPECT_NEAR(plan.shortened[0].offset_s, 0.875, 1e-9);
  }
  // The same quarter-beat rest at 60 bpm lasts 0.25 s: enough to breathe in without cutting.
  {
    const music::Score score = score_at(60);
    const BrassLine line = line_of({note_q(score, 0, 2), note_q(score, 2.25, 4.25)});
    BreathMarks marks;
    marks.add_s = {2.0};
    const BreathPlan plan = plan_breaths(line, score, fixed_params(), marks);
    ASSERT_EQ(plan.events.size(), 2u);
    const BreathEvent& e = plan.events[1];
    EXPECT_TRUE(e.marked);
    EXPECT_EQ(e.kind, BreathKind::in_rest);
    EXPECT_NEAR(e.window_start_s, 2.0, 1e-9);
    EXPECT_NEAR(e.start_s, 2.0, 1e-9);
    EXPECT_NEAR(e.end_s, 2.25, 1e-9);
    EXPECT_TRUE(plan.shortened.empty());
  }
  // A half-beat rest at 240 bpm (0.125 s) is long enough in beats but too short in seconds:
  // skipped by the rules, breathed in with the mark (and no longer counted as skipped).
  {
    const music::Score score = score_at(240);
    const BrassLine line = line_of({note_q(score, 0, 2), note_q(score, 2.5, 4.5)});
    const BreathPlan rules = plan_breaths(line, score, fixed_params());
    ASSERT_EQ(rules.events.size(), 1u);
    EXPECT_EQ(rules.skipped_rests, 1);
    BreathMarks marks;
    marks.add_s = {0.6};
    const BreathPlan plan = plan_breaths(line, score, fixed_params(), marks);
    ASSERT_EQ(plan.events.size(), 2u);
    EXPECT_TRUE(plan.events[1].marked);
    EXPECT_EQ(plan.events[1].before_note, 1);
    EXPECT_NEAR(plan.events[1].end_s, 0.625, 1e-9);
    EXPECT_EQ(plan.skipped_rests, 0);
  }
}

TEST(BreathMarks, AnAddMarkWhereTheRulesBreatheChangesNothing) {
  const music::Score score = score_at(120);
  const BrassLine line = line_of({note_q(score, 0, 2), note_q(score, 3.5, 5.5)});
  const BreathPlan rules = plan_breaths(line, score, fixed_params());
  ASSERT_EQ(rules.events.size(), 2u);
  BreathMarks marks;
  marks.add_s = {1.2, -4.0};  // the rest's breath and the one before the entrance
  const BreathPlan plan = plan_breaths(line, score, fixed_params(), marks);
  expect_same_plan(plan, rules);
  EXPECT_FALSE(plan.events[1].marked);
}

TEST(BreathMarks, ARemovedRuleBreathDisappearsAndNoneTakesItsPlace) {
  // A rest of 1.5 beats: the rules breathe in its last beat, before note 1.
  const music::Score score = score_at(120);
  const BrassLine line = line_of({note_q(score, 0, 2), note_q(score, 3.5, 5.5)});
  ASSERT_NE(event_before(plan_breaths(line, score, fixed_params()), 1), nullptr);
  BreathMarks marks;
  marks.remove_s = {1.0};  // the rest's start: the next onset is note 1's
  const BreathPlan plan = plan_breaths(line, score, fixed_params(), marks);
  ASSERT_EQ(plan.events.size(), 1u);
  EXPECT_EQ(plan.events[0].kind, BreathKind::before_entrance);
  EXPECT_EQ(event_before(plan, 1), nullptr);
  // The air runs on through the rest: constant there, then draining again.
  EXPECT_DOUBLE_EQ(evaluate_breath(plan, 1.2).air, evaluate_breath(plan, 1.7).air);
  EXPECT_LT(evaluate_breath(plan, 2.5).air, evaluate_breath(plan, 1.2).air);

  // The breath before the entrance can be removed too: the player starts on resting air.
  marks.remove_s = {-10.0};
  const BreathPlan no_entrance = plan_breaths(line, score, fixed_params(), marks);
  ASSERT_EQ(no_entrance.events.size(), 1u);
  EXPECT_EQ(no_entrance.events[0].before_note, 1);
  EXPECT_DOUBLE_EQ(evaluate_breath(no_entrance, 0.0).air, fixed_params().resting_air);
}

TEST(BreathMarks, ARemovedCatchBreathMovesElsewhereButNeverBackToItsBoundary) {
  // Forty legato quarters at 120 bpm (20 s): the air runs low and catch-breaths are needed.
  const music::Score score = score_at(120);
  const BrassLine line = legato_quarters(score, 40);
  const BreathPlan rules = plan_breaths(line, score, fixed_params());
  const BreathEvent* first_catch = nullptr;
  for (const BreathEvent& e : rules.events) {
    if (e.kind == BreathKind::catch_breath) {
      first_catch = &e;
      break;
    }
  }
  ASSERT_NE(first_catch, nullptr);
  const int boundary = first_catch->before_note;
  BreathMarks marks;
  marks.remove_s = {line.notes[static_cast<std::size_t>(boundary)].onset_s};
  const BreathPlan plan = plan_breaths(line, score, fixed_params(), marks);
  EXPECT_EQ(event_before(plan, boundary), nullptr);
  EXPECT_GT(plan.catch_breaths, 0) << "the air still runs out: a catch-breath elsewhere";
  for (const ShortenedNote& s : plan.shortened) EXPECT_NE(s.note, boundary - 1);
  test::expect_continuous(plan, -3.0, 21.0);
}

TEST(BreathMarks, MarksAfterTheLastNoteAreIgnoredAndCounted) {
  const music::Score score = score_at(120);
  const BrassLine line = line_of({note_q(score, 0, 2), note_q(score, 3.5, 5.5)});
  const BreathPlan rules = plan_breaths(line, score, fixed_params());
  BreathMarks marks;
  marks.add_s = {1.76, 100.0, std::numeric_limits<double>::quiet_NaN()};
  marks.remove_s = {2.0};  // after note 1's onset (1.75 s): no note left
  BreathPlan plan = plan_breaths(line, score, fixed_params(), marks);
  EXPECT_EQ(plan.ignored_marks, 4);
  plan.ignored_marks = 0;
  expect_same_plan(plan, rules);

  // A boundary both added and removed keeps no breath; the add is the ignored one.
  marks.add_s = {1.0};
  marks.remove_s = {1.0};
  const BreathPlan both = plan_breaths(line, score, fixed_params(), marks);
  EXPECT_EQ(both.ignored_marks, 1);
  EXPECT_EQ(event_before(both, 1), nullptr);

  // An empty line has nothing to mark.
  const BreathPlan empty = plan_breaths(line_of({}), score, fixed_params(), marks);
  EXPECT_EQ(empty.ignored_marks, 2);
  EXPECT_TRUE(empty.events.empty());
}

TEST(BreathMarks, PlansWithMarksAreDeterministic) {
  const music::Score score = score_at(120);
  const BrassLine line = legato_quarters(score, 40);
  BreathMarks marks;
  marks.add_s = {3.0, 7.25, 7.25, 12.0};
  marks.remove_s = {9.0, 15.5};
  const BreathPlan a = plan_breaths(line, score, fixed_params(), marks);
  const BreathPlan b = plan_breaths(line, score, fixed_params(), marks);
  expect_same_plan(a, b);
  // Order does not matter either.
  BreathMarks shuffled;
  shuffled.add_s = {12.0, 7.25, 3.0};
  shuffled.remove_s = {15.5, 9.0};
  expect_same_plan(plan_breaths(line, score, fixed_params(), shuffled), a);
  int marked = 0;
  for (const BreathEvent& e : a.events) marked += e.marked ? 1 : 0;
  EXPECT_EQ(marked, 3);
  EXPECT_EQ(event_before(a, 18), nullptr);  // 9.0 s
  EXPECT_EQ(event_before(a, 31), nullptr);  // 15.5 s
  test::expect_continuous(a, -3.0, 21.0);
}

}  // namespace
}  // namespace tutti::brass_motion
