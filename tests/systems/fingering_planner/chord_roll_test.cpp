// SPDX-License-Identifier: MIT
// Chords a hand cannot span are rolled (chord_roll.hpp): struck from the bottom up, a note let go
// before one out of its reach strikes; chords within reach are left as written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include <tutti/fingering_planner/chord_roll.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/music/load_score.hpp>
#include "planner_test_util.hpp"
#include "testdata.hpp"

namespace tutti::fingering_planner {
namespace {

music::Note note(int pitch, std::int64_t onset_ticks, std::int64_t offset_ticks, music::Hand hand) {
  music::Note n;
  n.pitch = pitch;
  n.onset_ticks = onset_ticks;
  n.offset_ticks = offset_ticks;
  n.hand = hand;
  n.staff = hand == music::Hand::left ? 2 : 1;
  return n;
}

const RolledNote* find(const ChordRolls& rolls, int index) {
  for (const RolledNote& r : rolls.notes) {
    if (r.note == index) return &r;
  }
  return nullptr;
}

// A left-hand tenth A2-E3-C#4 (a medium hand spans about a ninth) is rolled; the right hand's
// C5-E5-G5 triad at the same time, and the left hand's next chord (a sixth), are not.
TEST(ChordRoll, ATenthIsRolledFromTheBottomAndTheBassLetGoBeforeTheTopStrikes) {
  const FingeringModel& m = test::model("default");
  music::Score score;
  score.parts.push_back({});
  for (int pitch : {45, 52, 61}) score.notes.push_back(note(pitch, 960, 1920, music::Hand::left));
  for (int pitch : {72, 76, 79}) score.notes.push_back(note(pitch, 960, 1920, music::Hand::right));
  for (int pitch : {48, 52, 57}) score.notes.push_back(note(pitch, 1920, 2880, music::Hand::left));
  music::finalize_score(score);
  const double chord_s = score.notes[0].onset_s;
  const double chord_end_s = score.notes[0].offset_s;
  ASSERT_GT(chord_end_s - chord_s, 0.2);
  auto plan = plan_score(score, m);
  ASSERT_TRUE(plan) << plan.error().message;
  const ChordRolls rolls = plan_chord_rolls(score, *plan, m, 0.04);
  EXPECT_EQ(rolls.chords, 1) << test::fingers_text(plan->fingers);
  const RolledNote* bass = find(rolls, 0);
  const RolledNote* middle = find(rolls, 1);
  const RolledNote* top = find(rolls, 2);
  ASSERT_NE(bass, nullptr);
  ASSERT_NE(middle, nullptr);
  ASSERT_NE(top, nullptr);
  EXPECT_DOUBLE_EQ(bass->onset_s, chord_s);
  EXPECT_NEAR(middle->onset_s, chord_s + 0.04, 1e-9);
  EXPECT_NEAR(top->onset_s, chord_s + 0.08, 1e-9);
  EXPECT_LT(bass->release_s, top->onset_s);  // the little finger lets A2 go before C#4
  EXPECT_GT(bass->release_s, bass->onset_s);
  EXPECT_DOUBLE_EQ(top->release_s, chord_end_s);
  for (int i = 3; i < 9; ++i) EXPECT_EQ(find(rolls, i), nullptr) << i;

  // Planned again on the rolled notes with the same fingers: nothing left to roll.
  music::Score rolled = score;
  apply_chord_rolls(rolls, rolled);
  for (std::size_t i = 0; i < rolled.notes.size(); ++i) rolled.notes[i].finger = plan->fingers[i];
  auto again = plan_score(rolled, m);
  ASSERT_TRUE(again) << again.error().message;
  EXPECT_EQ(again->fingers, plan->fingers);
  EXPECT_TRUE(plan_chord_rolls(rolled, *again, m, 0.04).empty());
}

// Third-party scores: Chopin's Polonaise Op. 1 No. 3 has left-hand tenths (A2-E3-C#4 at 23 s),
// Scarlatti's K. 27 a right hand given D4 with B5 (122.9 s). Every chord rolled is one the hand
// could not span, and after the roll none is left.
TEST(ChordRoll, ThirdPartyChordsTooWideForTheHandAreRolledAndNoneRemain) {
  TUTTI_REQUIRE_TESTDATA();
  const FingeringModel& m = test::model("default");
  for (const char* file :
       {"musicxml/music21/polonaise_op1n3.mxl", "musicxml/pianoplayer/scarlatti_k027.xml"}) {
    auto score = music::load_score(tutti::test::testdata(file));
    ASSERT_TRUE(score) << score.error().message;
    auto plan = plan_score(*score, m);
    ASSERT_TRUE(plan) << plan.error().message;
    const ChordRolls rolls = plan_chord_rolls(*score, *plan, m);
    EXPECT_GT(rolls.chords, 0) << file;
    for (const RolledNote& r : rolls.notes) {
      const music::Note& written = score->notes[static_cast<std::size_t>(r.note)];
      EXPECT_GE(r.onset_s, written.onset_s) << file;
      EXPECT_LE(r.release_s, written.offset_s + 1e-9) << file;
      EXPECT_LT(r.onset_s, written.offset_s) << file;
    }
    music::Score rolled = *score;
    apply_chord_rolls(rolls, rolled);
    for (std::size_t i = 0; i < rolled.notes.size(); ++i) rolled.notes[i].finger = plan->fingers[i];
    auto again = plan_score(rolled, m);
    ASSERT_TRUE(again) << again.error().message;
    EXPECT_EQ(plan_chord_rolls(rolled, *again, m).chords, 0) << file;
  }
}

}  // namespace
}  // namespace tutti::fingering_planner
