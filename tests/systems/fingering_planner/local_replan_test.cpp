// SPDX-License-Identifier: MIT
// Re-planning after a pin: only the affected span changes, and the result is as good as a full
// re-plan with the same pins (on real pieces).
#include <tutti/fingering_planner/local_replan.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <tutti/fingering_planner/exact_planner.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/music/load_score.hpp>
#include "planner_test_util.hpp"
#include "testdata.hpp"

namespace tutti::fingering_planner {
namespace {

using music::Hand;

// The score with the file's fingering marks removed (planned from scratch, pins added by hand).
music::Score unmarked(const std::string& relative) {
  auto score = music::load_score(tutti::test::testdata(relative));
  EXPECT_TRUE(score.ok()) << (score.ok() ? "" : score.error().message);
  if (!score.ok()) return {};
  for (music::Note& n : score->notes) n.finger = 0;
  return std::move(*score);
}

double total_cost(const ScorePlan& plan) { return plan.right.total_cost + plan.left.total_cost; }

bool has_pin_conflict(const ScorePlan& plan) {
  for (const HandPlan* hand : {&plan.right, &plan.left}) {
    for (const Diagnostic& d : hand->diagnostics) {
      if (d.kind == DiagnosticKind::pin_conflict) return true;
    }
  }
  return false;
}

struct PieceFigures {
  int pins = 0;
  int same_cost_as_full = 0;
  double searched_fraction = 0.0;  // summed over pins
};

// The default weights with each hand planned alone (no other hand's room, other_hand_cost.hpp):
// then a hand's plan is the optimum of its own cost, and a local re-plan can be held to it.
const FingeringModel& hands_alone() {
  static const FingeringModel model = [] {
    FingeringModel m = test::model("default");
    m.weights.other_hand_per_white_key = 0.0;
    return m;
  }();
  return model;
}

// Pins `count` notes spread over the piece, one at a time from the unpinned plan, each to a
// finger other than the planned one, and checks the local re-plan against a full one. With the
// hands planned beside each other the score's plan is a sequence of hand plans, not one
// optimum, so `never_cheaper` (a local re-plan never beats the full one) holds only for hands
// planned alone.
PieceFigures check_single_pins(const std::string& relative, int count,
                               const FingeringModel& model, bool never_cheaper) {
  PieceFigures figures;
  const music::Score base = unmarked(relative);
  auto previous = plan_score(base, model);
  EXPECT_TRUE(previous.ok());
  if (!previous.ok() || base.notes.empty()) return figures;
  const std::size_t step = std::max<std::size_t>(1, base.notes.size() / std::size_t(count));
  for (std::size_t index = step / 2; index < base.notes.size(); index += step) {
    music::Score pinned = base;
    const int old_finger = previous->fingers[index];
    const int wanted = old_finger % 5 + 1;
    pinned.notes[index].finger = wanted;
    const int edited[] = {static_cast<int>(index)};
    ScoreReplanSpan span;
    auto local = replan_score_locally(pinned, model, {}, *previous, edited, &span);
    auto full = plan_score(pinned, model);
    EXPECT_TRUE(local.ok() && full.ok()) << relative;
    if (!local.ok() || !full.ok()) continue;
    SCOPED_TRACE(relative + " note " + std::to_string(index));
    if (!has_pin_conflict(*full)) {
      EXPECT_EQ(local->fingers[index], wanted);
    }
    // Outside the changed span nothing moved; inside, the pinned note did.
    int moved_outside = 0;
    for (std::size_t i = 0; i < base.notes.size(); ++i) {
      const double t = base.notes[i].onset_s;
      if (t < span.first_changed_s || t > span.last_changed_s || span.changed_notes == 0) {
        moved_outside += local->fingers[i] != previous->fingers[i];
      }
    }
    EXPECT_EQ(moved_outside, 0);
    int changed = 0;
    for (std::size_t i = 0; i < base.notes.size(); ++i) {
      changed += local->fingers[i] != previous->fingers[i];
    }
    EXPECT_EQ(changed, span.changed_notes);
    // Never worse than a full re-plan by more than rounding... or it is not a re-plan.
    if (never_cheaper) {
      EXPECT_GE(total_cost(*local) + 1e-6, total_cost(*full));
    }
    figures.same_cost_as_full += std::abs(total_cost(*local) - total_cost(*full)) < 1e-6;
    figures.searched_fraction += double(span.searched_events) / double(span.event_count);
    ++figures.pins;
  }
  return figures;
}

TEST(LocalReplan, PinsOnRealPiecesTouchOnlyTheAffectedSpan) {
  TUTTI_REQUIRE_TESTDATA();
  int pins = 0;
  int same = 0;
  for (const char* piece :
       {"musicxml/pianoplayer/bach_invention4.xml", "musicxml/pianoplayer/mozart_sonfacile.mxl",
        "musicxml/pianoplayer/scarlatti_k027.xml", "musicxml/pianoplayer/bach_prelude.xml",
        "musicxml/music21/polonaise_op1n1.mxl"}) {
    const PieceFigures f = check_single_pins(piece, 12, hands_alone(), true);
    ASSERT_GT(f.pins, 0) << piece;
    const double mean_searched = f.searched_fraction / f.pins;
    std::printf("%s: %d pins, %d with the full re-plan's cost, searched %.1f %% of events\n", piece,
                f.pins, f.same_cost_as_full, 100.0 * mean_searched);
    // A local edit searches a small part of a piece of hundreds of events.
    EXPECT_LT(mean_searched, 0.25) << piece;
    pins += f.pins;
    same += f.same_cost_as_full;
  }
  // The window stops when the change has died out; on real music that is the optimum nearly
  // always (60 of 60 pins when written; an exception is never cheaper than the full plan).
  EXPECT_GE(same, pins * 19 / 20);
}

// Beside the other hand (the default weights): pins are kept and nothing moves outside the
// changed span; the local re-plan is a full one's equal on most pins.
TEST(LocalReplan, PinsBesideTheOtherHandTouchOnlyTheAffectedSpan) {
  TUTTI_REQUIRE_TESTDATA();
  int pins = 0;
  int same = 0;
  for (const char* piece :
       {"musicxml/pianoplayer/bach_invention4.xml", "musicxml/pianoplayer/mozart_sonfacile.mxl",
        "musicxml/pianoplayer/scarlatti_k027.xml", "musicxml/music21/polonaise_op1n1.mxl"}) {
    const PieceFigures f = check_single_pins(piece, 12, test::model("default"), false);
    ASSERT_GT(f.pins, 0) << piece;
    EXPECT_LT(f.searched_fraction / f.pins, 0.25) << piece;
    pins += f.pins;
    same += f.same_cost_as_full;
  }
  std::printf("beside the other hand: %d of %d pins with the full re-plan's cost\n", same, pins);
  EXPECT_GE(same, pins * 3 / 4);  // 44 of 48 when written
}

TEST(LocalReplan, SuccessiveEditsKeepEveryPin) {
  TUTTI_REQUIRE_TESTDATA();
  music::Score score = unmarked("musicxml/pianoplayer/bach_invention4.xml");
  ASSERT_GT(score.notes.size(), 200u);
  const FingeringModel& model = test::model("default");
  auto plan = plan_score(score, model);
  ASSERT_TRUE(plan.ok());
  std::vector<int> pinned;
  for (int index : {40, 41, 120, 43, 180}) {
    const auto i = static_cast<std::size_t>(index);
    score.notes[i].finger = plan->fingers[i] % 5 + 1;
    const int edited[] = {index};
    auto next = replan_score_locally(score, model, {}, *plan, edited);
    ASSERT_TRUE(next.ok()) << next.error().message;
    plan = std::move(next);
    pinned.push_back(index);
    if (has_pin_conflict(*plan)) continue;
    for (int p : pinned) {
      EXPECT_EQ(plan->fingers[std::size_t(p)], score.notes[std::size_t(p)].finger) << p;
    }
  }
  // Unpinning lets the notes go back toward the free plan: never costlier than keeping the pin.
  const double pinned_cost = total_cost(*plan);
  score.notes[120].finger = 0;
  const int edited[] = {120};
  auto unpinned = replan_score_locally(score, model, {}, *plan, edited);
  ASSERT_TRUE(unpinned.ok());
  EXPECT_LE(total_cost(*unpinned), pinned_cost + 1e-9);
}

TEST(LocalReplan, NoEditLeavesThePlanAsItWas) {
  const auto notes = test::melody({60, 62, 64, 65, 67, 69, 71, 72, 71, 69, 67, 65, 64, 62, 60});
  const FingeringModel& model = test::model("default");
  auto plan = plan_hand_exact(notes, Hand::right, model);
  ASSERT_TRUE(plan.ok());
  auto same = replan_hand_locally(notes, Hand::right, model, *plan, {});
  ASSERT_TRUE(same.ok());
  EXPECT_EQ(same->plan.fingers, plan->fingers);
  EXPECT_EQ(same->changed_notes, 0);
  EXPECT_LT(same->searched_last_event, same->searched_first_event);
  EXPECT_DOUBLE_EQ(same->plan.total_cost, plan->total_cost);
}

TEST(LocalReplan, PinInALongMelodySearchesAWindowAndMatchesTheFullPlan) {
  std::vector<int> keys;
  for (int bar = 0; bar < 200; ++bar) {
    for (int k : {60, 62, 64, 65, 67, 65, 64, 62}) keys.push_back(k + (bar % 3) * 2);
  }
  auto notes = test::melody(keys, 0.2);
  const FingeringModel& model = test::model("default");
  auto plan = plan_hand_exact(notes, Hand::right, model);
  ASSERT_TRUE(plan.ok());
  const int index = 801;
  notes[index].pin = plan->fingers[index] % 5 + 1;
  const int edited[] = {index};
  auto local = replan_hand_locally(notes, Hand::right, model, *plan, edited);
  auto full = plan_hand_exact(notes, Hand::right, model);
  ASSERT_TRUE(local.ok() && full.ok());
  EXPECT_EQ(local->plan.fingers[index], notes[index].pin);
  EXPECT_NEAR(local->plan.total_cost, full->total_cost, 1e-9);
  EXPECT_FALSE(local->whole_hand);
  EXPECT_LT(local->searched_last_event - local->searched_first_event + 1, 100);
  // Deterministic.
  auto again = replan_hand_locally(notes, Hand::right, model, *plan, edited);
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again->plan.fingers, local->plan.fingers);
}

TEST(LocalReplan, RejectsAPlanOfAnotherPiece) {
  const auto notes = test::melody({60, 62, 64});
  HandPlan other;
  other.fingers = {1, 2};
  const int edited[] = {0};
  auto result = replan_hand_locally(notes, Hand::right, test::model("default"), other, edited);
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.error().message.find("2 fingers for 3 notes"), std::string::npos);
  HandPlan fine;
  fine.fingers = {1, 2, 3};
  const int outside[] = {3};
  EXPECT_FALSE(replan_hand_locally(notes, Hand::right, test::model("default"), fine, outside).ok());
}

}  // namespace
}  // namespace tutti::fingering_planner
