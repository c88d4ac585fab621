// SPDX-License-Identifier: MIT
// The streaming fingering planner: when it decides (lookahead, deadline, chords arriving late),
// what a key still down does, bounded memory, bad input, and its agreement with the exact and
// the paper's lookahead planner on real pieces.
#include <tutti/fingering_planner/streaming_planner.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include <tutti/fingering_planner/exact_planner.hpp>
#include <tutti/fingering_planner/live_hand_split.hpp>
#include <tutti/fingering_planner/streaming_piano.hpp>
#include <tutti/fingering_planner/streaming_report.hpp>
#include <tutti/music/load_score.hpp>
#include "planner_test_util.hpp"
#include "testdata.hpp"

namespace tutti::fingering_planner {
namespace {

using music::Hand;

StreamingHandPlanner make(int lookahead,
                          double max_wait_s = std::numeric_limits<double>::infinity(),
                          double chord_window_s = 0.0) {
  StreamingOptions options;
  options.lookahead = lookahead;
  options.max_wait_s = max_wait_s;
  options.chord_window_s = chord_window_s;
  auto planner = StreamingHandPlanner::create(test::model("default"), Hand::right, options);
  EXPECT_TRUE(planner.ok());
  return std::move(*planner);
}

PlanNote note(int key, double onset_s, double offset_s) { return {key, onset_s, offset_s, 0}; }

TEST(StreamingPlanner, RejectsBadOptions) {
  std::vector<StreamingOptions> bads(4);
  bads[0].lookahead = -1;
  bads[1].context_events = 0;
  bads[2].max_wait_s = -0.1;
  bads[3].chord_window_s = std::nan("");
  for (const StreamingOptions& bad : bads) {
    auto planner = StreamingHandPlanner::create(test::model("default"), Hand::right, bad);
    ASSERT_FALSE(planner.ok());
    EXPECT_NE(planner.error().message.find("streaming"), std::string::npos);
  }
  EXPECT_FALSE(StreamingHandPlanner::create(test::model("default"), Hand::unknown, {}).ok());
}

TEST(StreamingPlanner, LookaheadZeroDecidesAtArrival) {
  StreamingHandPlanner planner = make(0);
  std::vector<StreamedFinger> out;
  ASSERT_TRUE(planner.push(7, note(60, 1.0, 1.2), 1.2).ok());
  planner.advance(1.0, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].id, 7);
  EXPECT_EQ(out[0].decided_s, 1.0);
  EXPECT_EQ(out[0].future_events, 0);
  EXPECT_GE(out[0].finger, 1);
  EXPECT_LE(out[0].finger, 5);
}

TEST(StreamingPlanner, WaitsForItsLookahead) {
  StreamingHandPlanner planner = make(3);
  std::vector<StreamedFinger> out;
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(planner.push(i, note(60 + 2 * i, 0.25 * i, 0.25 * (i + 1)), 0.25 * (i + 1)).ok());
    planner.advance(0.25 * i, out);
  }
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(planner.pending_notes(), 3u);
  ASSERT_TRUE(planner.push(3, note(66, 0.75, 1.0), 1.0).ok());
  planner.advance(0.75, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].id, 0);
  EXPECT_EQ(out[0].future_events, 3);
  planner.flush(2.0, out);
  EXPECT_EQ(out.size(), 4u);
  EXPECT_EQ(planner.pending_notes(), 0u);
}

TEST(StreamingPlanner, DeadlineBoundsTheWait) {
  StreamingHandPlanner planner = make(6, 0.05);
  std::vector<StreamedFinger> out;
  ASSERT_TRUE(planner.push(1, note(64, 0.0, 0.5), std::nullopt).ok());
  planner.advance(0.049, out);
  EXPECT_TRUE(out.empty());
  planner.advance(0.05, out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].future_events, 0);
}

TEST(StreamingPlanner, LateChordNoteKeepsTheFingersGiven) {
  StreamingHandPlanner planner = make(0, 0.0, 0.03);
  std::vector<StreamedFinger> out;
  ASSERT_TRUE(planner.push(1, note(60, 0.0, 0.0), std::nullopt).ok());
  planner.advance(0.0, out);
  ASSERT_EQ(out.size(), 1u);
  const int first = out[0].finger;
  ASSERT_TRUE(planner.push(2, note(67, 0.012, 0.012), std::nullopt).ok());
  planner.advance(0.012, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[1].onset_s, 0.0);   // joined the chord
  EXPECT_GT(out[1].finger, first);  // right hand: the higher key, a higher finger
}

TEST(StreamingPlanner, KeyStillDownKeepsItsFinger) {
  // C4 struck, then a key up to a fifth away while C4 has no note-off yet: it needs another
  // finger, higher above C4 and lower below (right hand). Once C4's note-off has come the hand
  // is free, and for some keys the choice is a different one.
  int differ = 0;
  for (int key = 53; key <= 67; ++key) {
    if (key == 60) continue;
    std::array<int, 2> second{};
    for (bool released : {false, true}) {
      StreamingHandPlanner planner = make(0);
      std::vector<StreamedFinger> out;
      ASSERT_TRUE(planner.push(1, note(60, 0.0, 0.0), std::nullopt).ok());
      planner.advance(0.0, out);
      if (released) planner.note_off(1, 0.1);
      ASSERT_TRUE(planner.push(2, note(key, 0.3, 0.3), std::nullopt).ok());
      planner.advance(0.3, out);
      ASSERT_EQ(out.size(), 2u);
      if (!released) {
        const bool ordered =
            key > 60 ? out[1].finger > out[0].finger : out[1].finger < out[0].finger;
        EXPECT_TRUE(ordered) << key << ": C4 is still down under finger " << out[0].finger;
      }
      second[released ? 1 : 0] = out[1].finger;
    }
    differ += second[0] != second[1] ? 1 : 0;
  }
  EXPECT_GT(differ, 0);
}

TEST(StreamingPlanner, MemoryIsBounded) {
  StreamingHandPlanner planner = make(3);
  std::vector<StreamedFinger> out;
  std::size_t most = 0;
  for (int i = 0; i < 2000; ++i) {
    const double t = 0.1 * i;
    ASSERT_TRUE(planner.push(i, note(60 + (i * 7) % 24, t, t + 0.1), t + 0.1).ok());
    planner.advance(t, out);
    most = std::max(most, planner.window_size());
  }
  EXPECT_LE(most, 4u + 1u + 3u + 1u);  // context + current + lookahead (+ the one just pushed)
  // Keys never released (lost note-offs): still bounded.
  StreamingHandPlanner stuck = make(0);
  for (int i = 0; i < 500; ++i) {
    ASSERT_TRUE(stuck.push(i, note(40 + i % 40, 0.1 * i, 0.1 * i), std::nullopt).ok());
    stuck.advance(0.1 * i, out);
  }
  EXPECT_LE(stuck.window_size(), 64u);
}

TEST(StreamingPlanner, RejectsBadNotes) {
  StreamingHandPlanner planner = make(0);
  std::vector<StreamedFinger> out;
  auto off_keyboard = planner.push(1, note(10, 0.0, 0.1), 0.1);
  ASSERT_FALSE(off_keyboard.ok());
  EXPECT_NE(off_keyboard.error().message.find("note 1: key 10"), std::string::npos);
  EXPECT_FALSE(planner.push(2, note(60, 0.5, 0.4), 0.4).ok());  // offset < onset
  EXPECT_FALSE(planner.push(3, note(60, std::nan(""), 0.4), std::nullopt).ok());
  ASSERT_TRUE(planner.push(4, note(60, 1.0, 1.0), std::nullopt).ok());
  EXPECT_FALSE(planner.push(4, note(62, 1.5, 1.5), std::nullopt).ok());  // id in use
  auto earlier = planner.push(5, note(62, 0.5, 0.5), std::nullopt);
  ASSERT_FALSE(earlier.ok());
  EXPECT_NE(earlier.error().message.find("before the previous"), std::string::npos);
}

TEST(LiveHandSplit, NearestHandThatCanTakeTheKey) {
  LiveHandSplit split(test::model("default"));
  EXPECT_EQ(split.assign(1, 72), Hand::right);
  EXPECT_EQ(split.assign(2, 43), Hand::left);
  EXPECT_EQ(split.assign(3, 70), Hand::right);  // near the right hand's last key
  // The right hand holds 72 and 70: a key far below goes to the left hand even if the right
  // hand was nearer before, and the left never plays above a key the right holds.
  EXPECT_EQ(split.assign(4, 52), Hand::left);
  EXPECT_EQ(split.assign(5, 74), Hand::right);
  split.release(1);
  split.release(3);
  split.release(5);
  EXPECT_EQ(split.held(Hand::right), 0u);
  EXPECT_EQ(split.held(Hand::left), 2u);
  // The left holds 43 and 52: 50 is nearer the left's last key and it can take it.
  EXPECT_EQ(split.assign(6, 50), Hand::left);
  // Five keys down in the right hand: the sixth goes to the left.
  for (int i = 0; i < 5; ++i) EXPECT_EQ(split.assign(10 + i, 76 + i), Hand::right);
  split.release(2);
  split.release(4);
  split.release(6);
  EXPECT_EQ(split.assign(20, 75), Hand::left);
}

// Real pieces: every piano piece of the test data and the demo.
std::vector<music::Score> pieces() {
  std::vector<music::Score> scores;
  std::vector<std::filesystem::path> files = {tutti::test::source_dir() /
                                              "content/music/ode_to_joy.musicxml"};
  for (const char* name :
       {"musicxml/pianoplayer/bach_invention4.xml", "musicxml/pianoplayer/bach_prelude.xml",
        "musicxml/pianoplayer/mozart_sonfacile.mxl", "musicxml/pianoplayer/pachelbel_canon.xml",
        "musicxml/pianoplayer/scarlatti_k027.xml", "musicxml/music21/polonaise_op1n1.mxl",
        "musicxml/music21/polonaise_op1n2.mxl", "musicxml/music21/polonaise_op1n3.mxl",
        "musicxml/music21/polonaise_op1n4.mxl", "midi/tonejs/bach_846.mid"}) {
    files.push_back(tutti::test::testdata(name));
  }
  for (const auto& file : files) {
    auto score = music::load_score(file);
    EXPECT_TRUE(score.ok()) << file;
    if (!score.ok()) continue;
    for (music::Note& n : score->notes) n.finger = 0;
    scores.push_back(std::move(*score));
  }
  return scores;
}

TEST(StreamingAgreement, ImprovesWithLookaheadOnRealPieces) {
  TUTTI_REQUIRE_TESTDATA();
  const std::vector<music::Score> scores = pieces();
  ASSERT_EQ(scores.size(), 11u);
  struct Total {
    int notes = 0, same = 0, paper = 0;
    double cost = 0, exact = 0;
  };
  std::vector<Total> totals;
  for (int lookahead : {0, 3, 6}) {
    Total total;
    for (const music::Score& score : scores) {
      auto a = measure_streaming_agreement(score, test::model("default"), lookahead);
      ASSERT_TRUE(a.ok()) << a.error().message;
      total.notes += a->notes;
      total.same += a->same_finger();
      total.paper += a->same_as_lookahead_planner;
      total.cost += a->right.streaming_cost + a->left.streaming_cost;
      total.exact += a->right.exact_cost + a->left.exact_cost;
      EXPECT_GE(a->cost_ratio(), 1.0 - 1e-9) << score.source << ": cheaper than the optimum";
    }
    totals.push_back(total);
    const double agreement = double(total.same) / total.notes;
    std::printf(
        "lookahead %d: %d notes, %.1f %% as exact, cost x %.3f, %.1f %% as lookahead "
        "planner (%d)\n",
        lookahead, total.notes, 100 * agreement, total.cost / total.exact,
        100.0 * total.paper / total.notes, lookahead + 1);
    // The search is the paper's: the same decisions as plan_hand_lookahead(L + 1) but where the
    // two planners' fallbacks for a held key that cannot keep its finger differ.
    EXPECT_GE(double(total.paper) / total.notes, 0.98);
  }
  for (std::size_t i = 1; i < totals.size(); ++i) {
    EXPECT_GT(totals[i].same, totals[i - 1].same);
    EXPECT_LT(totals[i].cost, totals[i - 1].cost);
  }
  // The README's floors.
  EXPECT_GE(double(totals[0].same) / totals[0].notes, 0.45);
  EXPECT_GE(double(totals[1].same) / totals[1].notes, 0.80);
  EXPECT_GE(double(totals[2].same) / totals[2].notes, 0.92);
  EXPECT_LE(totals[2].cost / totals[2].exact, 1.01);
}

TEST(StreamingAgreement, UnboundedLookaheadIsTheExactPlan) {
  // Waiting for every later note, each decision is the exact DP's from the past it keeps, and
  // by the DP's optimality its first step is the exact plan's.
  auto score = music::load_score(tutti::test::source_dir() / "content/music/ode_to_joy.musicxml");
  ASSERT_TRUE(score.ok());
  auto a = measure_streaming_agreement(*score, test::model("default"), 100000);
  ASSERT_TRUE(a.ok());
  EXPECT_EQ(a->same_finger(), a->notes);
  EXPECT_NEAR(a->cost_ratio(), 1.0, 1e-12);
}

TEST(StreamingAgreement, Deterministic) {
  auto score = music::load_score(tutti::test::source_dir() / "content/music/ode_to_joy.musicxml");
  ASSERT_TRUE(score.ok());
  auto a = measure_streaming_agreement(*score, test::model("default"), 3);
  auto b = measure_streaming_agreement(*score, test::model("default"), 3);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a->same_finger(), b->same_finger());
  EXPECT_EQ(a->split_same_finger, b->split_same_finger);
  EXPECT_EQ(a->right.streaming_cost, b->right.streaming_cost);
  EXPECT_EQ(a->left.streaming_cost, b->left.streaming_cost);
}

}  // namespace
}  // namespace tutti::fingering_planner
