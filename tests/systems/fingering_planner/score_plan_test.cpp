// SPDX-License-Identifier: MIT
// Whole scores: hand assignment, chords, octaves, pins, determinism, editors' marks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <vector>

#include <tutti/fingering_planner/exact_planner.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/fingering_planner/transition_cost.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/music/pitch.hpp>
#include "planner_test_util.hpp"
#include "testdata.hpp"

namespace tutti::fingering_planner {
namespace {

using music::Hand;

music::Score load(const std::string& relative) {
  auto score = music::load_score(tutti::test::testdata(relative));
  EXPECT_TRUE(score.ok()) << (score.ok() ? "" : score.error().message);
  return score.ok() ? std::move(*score) : music::Score{};
}

// Every note fingered; notes starting together in one hand get distinct fingers ordered by key.
void expect_chords_well_formed(const music::Score& score, const ScorePlan& plan) {
  std::map<std::pair<std::int64_t, int>, std::vector<std::size_t>> events;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    ASSERT_GE(plan.fingers[i], 1) << i;
    ASSERT_LE(plan.fingers[i], 5) << i;
    events[{score.notes[i].onset_ticks, int(plan.hands[i])}].push_back(i);
  }
  for (auto& [at, notes] : events) {
    std::sort(notes.begin(), notes.end(),
              [&](auto a, auto b) { return score.notes[a].pitch < score.notes[b].pitch; });
    for (std::size_t k = 1; k < notes.size(); ++k) {
      if (score.notes[notes[k]].pitch == score.notes[notes[k - 1]].pitch) continue;
      const int lower = plan.fingers[notes[k - 1]];
      const int upper = plan.fingers[notes[k]];
      if (at.second == int(Hand::right)) {
        EXPECT_LT(lower, upper) << "tick " << at.first;
      } else {
        EXPECT_GT(lower, upper) << "tick " << at.first;
      }
    }
  }
}

TEST(ScorePlan, ChordsAreFingeredDistinctAndOrdered) {
  TUTTI_REQUIRE_TESTDATA();
  const music::Score score = load("musicxml/pianoplayer/test_chords.xml");
  auto plan = plan_score(score, test::model("default"));
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    EXPECT_EQ(plan->hands[i], score.notes[i].staff == 1 ? Hand::right : Hand::left);
  }
  expect_chords_well_formed(score, *plan);
  // C-E-G-B-D (five keys) in the right hand: 1-2-3-4-5.
  std::printf("[ chords  ] right cost %.2f, left cost %.2f, %zu+%zu diagnostics\n",
              plan->right.total_cost, plan->left.total_cost, plan->right.diagnostics.size(),
              plan->left.diagnostics.size());
}

TEST(ScorePlan, OctavesArePlayedOneFive) {
  TUTTI_REQUIRE_TESTDATA();
  const music::Score score = load("musicxml/pianoplayer/test_octaves.xml");
  for (const char* weights : {"default", "paper"}) {
    auto plan = plan_score(score, test::model(weights));
    ASSERT_TRUE(plan.ok()) << plan.error().message;
    expect_chords_well_formed(score, *plan);
    std::map<std::int64_t, std::vector<std::size_t>> by_onset;
    for (std::size_t i = 0; i < score.notes.size(); ++i)
      by_onset[score.notes[i].onset_ticks].push_back(i);
    for (const auto& [tick, notes] : by_onset) {
      ASSERT_EQ(notes.size(), 2u);
      EXPECT_EQ(plan->hands[notes[0]], plan->hands[notes[1]]) << "one hand per octave";
      const int a = plan->fingers[notes[0]];
      const int b = plan->fingers[notes[1]];
      EXPECT_EQ(std::min(a, b), 1) << weights << " tick " << tick;
      EXPECT_GE(std::max(a, b), 4) << weights << " tick " << tick;  // 5, or 4 on black octaves
    }
  }
}

TEST(ScorePlan, Deterministic) {
  TUTTI_REQUIRE_TESTDATA();
  const music::Score score = load("musicxml/pianoplayer/test_scales.xml");
  auto a = plan_score(score, test::model("default"));
  auto b = plan_score(score, test::model("default"));
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a->fingers, b->fingers);
  EXPECT_EQ(a->right.total_cost, b->right.total_cost);
  EXPECT_EQ(a->left.corridors.size(), b->left.corridors.size());
}

TEST(ScorePlan, PinsAreHardConstraintsAndTheRestIsReplanned) {
  const std::vector<int> keys = {60, 62, 64, 65, 67, 69, 71, 72};
  auto notes = test::melody(keys);
  auto free_plan = plan_hand_exact(notes, Hand::right, test::model("default"));
  ASSERT_TRUE(free_plan.ok());
  EXPECT_EQ(test::fingers_text(free_plan->fingers), "12312345");
  notes[3].pin = 4;  // F with 4: 1234 1234 style
  auto pinned = plan_hand_exact(notes, Hand::right, test::model("default"));
  ASSERT_TRUE(pinned.ok());
  EXPECT_EQ(pinned->fingers[3], 4);
  EXPECT_EQ(pinned->fingers[4], 1) << test::fingers_text(pinned->fingers);
  EXPECT_EQ(pinned->impossible_transitions, 0);
  // Pins from the file's marks, through plan_score.
  music::Score score;
  score.parts.push_back({});
  for (std::size_t i = 0; i < keys.size(); ++i) {
    music::Note n;
    n.pitch = keys[i];
    n.onset_ticks = std::int64_t(i) * 240;
    n.offset_ticks = n.onset_ticks + 240;
    n.hand = Hand::right;
    score.notes.push_back(n);
  }
  score.notes[2].finger = 2;
  music::finalize_score(score);
  auto plan = plan_score(score, test::model("default"));
  ASSERT_TRUE(plan.ok());
  EXPECT_EQ(plan->fingers[2], 2);
}

TEST(ScorePlan, SixKeysAtOnceAndUnreachableSpansAreReportedButFingered) {
  std::vector<PlanNote> notes;
  for (int key : {60, 62, 64, 65, 67, 69}) notes.push_back({key, 0.0, 1.0, 0});
  notes.push_back({48, 1.0, 2.0, 0});  // then a 2-octave chord
  notes.push_back({72, 1.0, 2.0, 0});
  auto plan = plan_hand_exact(notes, Hand::right, test::model("default"));
  ASSERT_TRUE(plan.ok());
  for (int f : plan->fingers) EXPECT_GE(f, 1);
  bool too_many = false, unreachable = false;
  for (const Diagnostic& d : plan->diagnostics) {
    too_many |= d.kind == DiagnosticKind::too_many_notes && d.notes.size() == 6;
    unreachable |= d.kind == DiagnosticKind::unreachable_span;
    EXPECT_NE(d.message.find("at "), std::string::npos) << d.message;
  }
  EXPECT_TRUE(too_many);
  EXPECT_TRUE(unreachable);
  EXPECT_EQ(plan->fingers[6], 1);
  EXPECT_EQ(plan->fingers[7], 5);
}

TEST(ScorePlan, HeldNotesKeepTheirFingerAndConstrainTheHand) {
  // C4 held for the whole bar while E4, F4, G4 are played above it.
  std::vector<PlanNote> notes = {{60, 0.0, 2.0, 0},
                                 {64, 0.0, 0.5, 0},
                                 {65, 0.5, 1.0, 0},
                                 {67, 1.0, 1.5, 0},
                                 {64, 1.5, 2.0, 0}};
  auto plan = plan_hand_exact(notes, Hand::right, test::model("default"));
  ASSERT_TRUE(plan.ok());
  for (std::size_t i = 1; i < notes.size(); ++i) {
    EXPECT_NE(plan->fingers[i], plan->fingers[0]) << test::fingers_text(plan->fingers);
  }
}

TEST(ScorePlan, InvalidInputIsAnError) {
  std::vector<PlanNote> notes = {{10, 0.0, 1.0, 0}};
  auto plan = plan_hand_exact(notes, Hand::right, test::model("default"));
  ASSERT_FALSE(plan.ok());
  EXPECT_NE(plan.error().message.find("note 0: key 10 is not on the keyboard"), std::string::npos);
}

TEST(ScorePlan, AutomaticSplitKeepsAMelodyInOneHandAndSplitsWideChords) {
  music::Score score;
  score.parts.push_back({});
  auto add = [&](int pitch, std::int64_t tick) {
    music::Note n;
    n.pitch = pitch;
    n.onset_ticks = tick;
    n.offset_ticks = tick + 480;
    score.notes.push_back(n);
  };
  for (int i = 0; i < 8; ++i) add(67 + (i % 3), i * 480);
  add(36, 8 * 480);  // bass + melody: two hands
  add(43, 8 * 480);
  add(76, 8 * 480);
  music::finalize_score(score);
  const HandAssignment a = assign_hands(score, test::model("default"));
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    const Hand expected = score.notes[i].pitch < 60 ? Hand::left : Hand::right;
    EXPECT_EQ(a.hand[i], expected) << score.notes[i].pitch;
    EXPECT_EQ(a.source[i], HandSource::automatic);
  }
}

// Bach's C major fugue (BWV 846) comes as four voice tracks with no hands: they are split
// together, so neither hand is given a span it cannot reach (split per track, the right hand got
// voices 1 and 2 and tenths like C4-E5).
TEST(ScorePlan, VoicesOnSeparateTracksAreSplitTogether) {
  TUTTI_REQUIRE_TESTDATA();
  const music::Score score = load("midi/tonejs/bach_846.mid");
  const HandAssignment a = assign_hands(score, test::model("default"));
  int fugue_right = 0;
  int fugue_left = 0;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    if (score.parts[std::size_t(score.notes[i].part)].name.rfind("Fuga", 0) != 0) continue;
    // Split automatically; a few close two-voice passages then go to one hand (crowded).
    EXPECT_TRUE(a.source[i] == HandSource::automatic || a.source[i] == HandSource::crowded);
    (a.hand[i] == Hand::right ? fugue_right : fugue_left) += 1;
  }
  EXPECT_GT(fugue_right, 100);
  EXPECT_GT(fugue_left, 100);
  auto plan = plan_score(score, test::model("default"));
  ASSERT_TRUE(plan.ok());
  for (const HandPlan* hand : {&plan->right, &plan->left}) {
    for (const Diagnostic& d : hand->diagnostics) {
      EXPECT_NE(d.kind, DiagnosticKind::unreachable_span) << d.message;
    }
  }
}

// Editors' fingering in Clara Schumann's polonaises: how often the planner agrees.
struct Agreement {
  int marked = 0;
  int matched = 0;
  int notes = 0;
};

Agreement polonaise_agreement(const std::string& weights) {
  Agreement total;
  for (int n = 1; n <= 4; ++n) {
    music::Score score = load("musicxml/music21/polonaise_op1n" + std::to_string(n) + ".mxl");
    std::vector<int> marks;
    for (music::Note& note : score.notes) {
      marks.push_back(note.finger);
      note.finger = 0;
    }
    auto plan = plan_score(score, test::model(weights));
    EXPECT_TRUE(plan.ok());
    if (!plan.ok()) continue;
    Agreement one;
    for (std::size_t i = 0; i < marks.size(); ++i) {
      EXPECT_GE(plan->fingers[i], 1);
      if (marks[i] == 0) continue;
      ++one.marked;
      one.matched += plan->fingers[i] == marks[i];
    }
    one.notes = int(marks.size());
    std::printf("[ polonaise] op1n%d %s: %d/%d marks (%.1f%%), %d notes, %zu+%zu diagnostics\n", n,
                weights.c_str(), one.matched, one.marked,
                one.marked ? 100.0 * one.matched / one.marked : 0.0, one.notes,
                plan->right.diagnostics.size(), plan->left.diagnostics.size());
    total.marked += one.marked;
    total.matched += one.matched;
    total.notes += one.notes;
  }
  std::printf("[ polonaise] all %s: %d/%d marks (%.1f%%)\n", weights.c_str(), total.matched,
              total.marked, total.marked ? 100.0 * total.matched / total.marked : 0.0);
  return total;
}

TEST(ScorePlan, PolonaisesAgreeWithTheEditorsMarks) {
  TUTTI_REQUIRE_TESTDATA();
  const Agreement defaults = polonaise_agreement("default");
  const Agreement paper = polonaise_agreement("paper");
  ASSERT_GT(defaults.marked, 0);
  // Measured: default 41/57, paper 40/57 (the marks are few and mostly unambiguous).
  EXPECT_GE(double(defaults.matched) / defaults.marked, 0.70);
  EXPECT_GE(double(paper.matched) / paper.marked, 0.70);
}

}  // namespace
}  // namespace tutti::fingering_planner

namespace tutti::fingering_planner {
namespace {

// A legato leap (C4 then C6, each held until the next): the hand areas cannot overlap, so the
// planner prices the move over its effective time (the shift time: the first key let go early)
// and the first corridor must end when that move starts, never touching the next one.
TEST(ScorePlan, CorridorsLeaveTheBudgetedTravelTimeBeforeALeap) {
  const auto notes = test::melody({60, 84, 84}, 0.5);
  const CostWeights& w = test::model("default").weights;
  auto plan = plan_hand_exact(notes, music::Hand::right, test::model("default"));
  ASSERT_TRUE(plan.ok()) << plan.error().message;
  ASSERT_EQ(plan->corridors.size(), 3u);
  const HandCorridor& first = plan->corridors[0];
  const HandCorridor& second = plan->corridors[1];
  ASSERT_LT(first.hi_mm, second.lo_mm);  // disjoint: the hand must travel
  const double dt = effective_dt(0.0, 0.5, w);
  ASSERT_GT(w.shift_time_s, w.release_fraction * 0.5);  // the shift time decides here
  EXPECT_DOUBLE_EQ(dt, std::min(w.shift_time_s, (1 - w.shift_hold_fraction) * 0.5));
  EXPECT_NEAR(first.end_s, 0.5 - dt, 1e-12);
  EXPECT_LT(first.end_s, second.start_s);
  // Same key again: the areas overlap, so that corridor keeps its whole duration.
  EXPECT_DOUBLE_EQ(second.end_s, 1.0);
}

}  // namespace
}  // namespace tutti::fingering_planner
