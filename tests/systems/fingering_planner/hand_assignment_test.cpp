// SPDX-License-Identifier: MIT
// Which hand plays each note: a chord the score gives one hand but no hand can span goes, in
// part, to the other hand when it is free (Scarlatti's K. 27 writes D4 and B5 together on the
// right-hand staff); when the other hand is busy, or the file states the hands, nothing moves.
#include <gtest/gtest.h>

#include <vector>

#include <tutti/fingering_planner/hand_assignment.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/music/load_score.hpp>
#include "planner_test_util.hpp"
#include "testdata.hpp"

namespace tutti::fingering_planner {
namespace {

using music::Hand;

// A two-staff piano part: staff 1 the right hand, staff 2 the left.
struct PianoScore {
  music::Score score;
  PianoScore() {
    music::Part part;
    part.staves = 2;
    score.parts.push_back(part);
  }
  void add(int pitch, std::int64_t tick, std::int64_t length, int staff) {
    music::Note n;
    n.pitch = pitch;
    n.onset_ticks = tick;
    n.offset_ticks = tick + length;
    n.staff = staff;
    score.notes.push_back(n);
  }
  Hand hand_of(const HandAssignment& a, int pitch, std::int64_t tick) const {
    for (std::size_t i = 0; i < score.notes.size(); ++i) {
      if (score.notes[i].pitch == pitch && score.notes[i].onset_ticks == tick) return a.hand[i];
    }
    return Hand::unknown;
  }
  std::size_t index_of(int pitch, std::int64_t tick) const {
    for (std::size_t i = 0; i < score.notes.size(); ++i) {
      if (score.notes[i].pitch == pitch && score.notes[i].onset_ticks == tick) return i;
    }
    ADD_FAILURE() << "no note " << pitch << " at " << tick;
    return 0;
  }
};

TEST(HandAssignment, AChordOneHandCannotSpanGivesItsLowNoteToTheFreeLeftHand) {
  PianoScore s;
  s.add(62, 0, 480, 1);  // D4 and B5 together on the right-hand staff: an octave and a sixth
  s.add(83, 0, 240, 1);
  s.add(76, 240, 240, 1);
  s.add(43, 960, 480, 2);  // the left hand plays only later
  music::finalize_score(s.score);
  const HandAssignment a = assign_hands(s.score, test::model("default"));
  EXPECT_EQ(s.hand_of(a, 62, 0), Hand::left);
  EXPECT_EQ(s.hand_of(a, 83, 0), Hand::right);
  EXPECT_EQ(s.hand_of(a, 76, 240), Hand::right);
  EXPECT_EQ(s.hand_of(a, 43, 960), Hand::left);
  for (std::size_t i = 0; i < s.score.notes.size(); ++i) {
    EXPECT_EQ(a.source[i], s.score.notes[i].pitch == 62 ? HandSource::reach : HandSource::staff);
  }
}

TEST(HandAssignment, AReachableChordStaysWithItsStaff) {
  PianoScore s;
  s.add(60, 0, 480, 1);  // an octave: one hand spans it
  s.add(72, 0, 480, 1);
  s.add(48, 0, 480, 2);
  music::finalize_score(s.score);
  const HandAssignment a = assign_hands(s.score, test::model("default"));
  EXPECT_EQ(s.hand_of(a, 60, 0), Hand::right);
  EXPECT_EQ(s.hand_of(a, 72, 0), Hand::right);
  EXPECT_EQ(s.hand_of(a, 48, 0), Hand::left);
}

// The left hand reaches as far as the right (its ranges mirror the right's): its octaves and
// fifths stay with it even while the right hand is free to take their top notes. (Its reach once
// read 0 mm, so every left-hand chord gave its top note to a free right hand, and the thumbs met.)
TEST(HandAssignment, ALeftHandChordItCanSpanStaysWithIt) {
  PianoScore s;
  s.add(45, 0, 240, 2);  // A2-A3, B2-B3, D3-A3 on the left-hand staff; the right hand rests
  s.add(57, 0, 240, 2);
  s.add(47, 240, 240, 2);
  s.add(59, 240, 240, 2);
  s.add(50, 480, 240, 2);
  s.add(57, 480, 240, 2);
  s.add(79, 960, 480, 1);
  music::finalize_score(s.score);
  const HandAssignment a = assign_hands(s.score, test::model("default"));
  for (std::size_t i = 0; i + 1 < s.score.notes.size(); ++i) {
    EXPECT_EQ(a.hand[i], Hand::left) << s.score.notes[i].pitch;
    EXPECT_EQ(a.source[i], HandSource::staff) << s.score.notes[i].pitch;
  }
  const FingeringModel& model = test::model("default");
  EXPECT_NEAR(model.hand.reach_mm(), 8.0 * model.keyboard.white_key_width_mm(), 1e-9);
}

TEST(HandAssignment, ABusyOrCrossingOtherHandTakesNothing) {
  {
    PianoScore s;  // the left hand holds a chord far below: it cannot also reach D4
    s.add(62, 0, 480, 1);
    s.add(83, 0, 480, 1);
    s.add(36, 0, 480, 2);
    s.add(43, 0, 480, 2);
    music::finalize_score(s.score);
    const HandAssignment a = assign_hands(s.score, test::model("default"));
    EXPECT_EQ(s.hand_of(a, 62, 0), Hand::right);
  }
  {
    PianoScore s;  // the left hand plays A3 and F4 meanwhile: D4 would land between its keys
    s.add(62, 0, 480, 1);
    s.add(83, 0, 480, 1);
    s.add(57, 120, 240, 2);
    s.add(65, 120, 240, 2);
    music::finalize_score(s.score);
    const HandAssignment a = assign_hands(s.score, test::model("default"));
    EXPECT_EQ(s.hand_of(a, 62, 0), Hand::right);
  }
}

// A right-hand note under the left hand's keys goes to the left hand as its lowest key (Chopin's
// op. 1 no. 4: G3 in the right hand's staff under the left hand's held D4-G4); with D4 and B5 at
// once, D4 goes to a left hand that plays F4 meanwhile, below it. A note the other hand cannot
// span with its keys (C#3 under a left hand on C#4-G4) stays where it is. The same key struck by
// the other hand just before, or while it holds it, is the other hand's (the thumbs would meet
// on it); a new key is not.
TEST(HandAssignment, ANoteUnderTheOtherHandsKeysGoesToItAtItsOuterSide) {
  struct Added {
    int pitch;
    std::int64_t tick, length;
    int staff;
  };
  const struct {
    std::vector<Added> notes;
    int pitch;  // the note asked about, at `tick`
    std::int64_t tick;
    Hand expected;
  } cases[] = {
      {{{62, 0, 960, 2}, {67, 0, 960, 2}, {77, 0, 480, 1}, {55, 480, 960, 1}}, 55, 480, Hand::left},
      {{{62, 0, 480, 1}, {83, 0, 480, 1}, {65, 120, 240, 2}}, 62, 0, Hand::left},
      {{{61, 0, 960, 2}, {64, 0, 960, 2}, {67, 0, 960, 2}, {49, 480, 960, 1}}, 49, 480, Hand::right},
      // D4 handed from the left thumb to the right as the left lets it go: the left plays both.
      {{{62, 0, 240, 2}, {62, 240, 240, 1}, {81, 960, 480, 1}}, 62, 240, Hand::left},
      // G5 struck by the right hand while the left holds it with D#5: the left strikes it again.
      {{{75, 0, 960, 2}, {79, 0, 960, 2}, {79, 240, 120, 1}}, 79, 240, Hand::left},
      // A line passing from one hand to the other on a new key stays as written.
      {{{62, 0, 240, 2}, {64, 240, 240, 1}}, 64, 240, Hand::right},
  };
  for (const auto& c : cases) {
    PianoScore s;
    for (const Added& n : c.notes) s.add(n.pitch, n.tick, n.length, n.staff);
    music::finalize_score(s.score);
    const HandAssignment a = assign_hands(s.score, test::model("default"));
    EXPECT_EQ(s.hand_of(a, c.pitch, c.tick), c.expected) << c.pitch;
    if (c.expected == Hand::left) {
      EXPECT_EQ(a.source[s.index_of(c.pitch, c.tick)], HandSource::crossing) << c.pitch;
    }
    for (const Added& n : c.notes) {  // the right hand's other keys stay with it
      if (n.staff == 1 && n.pitch != c.pitch) {
        EXPECT_EQ(s.hand_of(a, n.pitch, n.tick), Hand::right) << n.pitch;
      }
    }
  }
}

// Two lines written crossing note by note (the lilypond suite's 43e: the right hand's staff
// C#5-B4-A4 against the left's B4-C#5-D5, a half-beat each). A key a hand lets go as the crossed
// note strikes does not keep that note in it: no onset has the hands crossed.
TEST(HandAssignment, LinesCrossingNoteByNoteAreTradedAtEachStrike) {
  PianoScore s;
  s.add(73, 0, 480, 1);  // right: C#5, B4, A4
  s.add(71, 480, 480, 1);
  s.add(69, 960, 480, 1);
  s.add(71, 0, 480, 2);  // left: B4, C#5, D5
  s.add(73, 480, 480, 2);
  s.add(74, 960, 480, 2);
  music::finalize_score(s.score);
  const HandAssignment a = assign_hands(s.score, test::model("default"));
  for (const std::int64_t tick : {0, 480, 960}) {
    int left_top = -1, right_bottom = 128;
    for (std::size_t i = 0; i < s.score.notes.size(); ++i) {
      if (s.score.notes[i].onset_ticks != tick) continue;
      if (a.hand[i] == Hand::left) left_top = std::max(left_top, s.score.notes[i].pitch);
      if (a.hand[i] == Hand::right) right_bottom = std::min(right_bottom, s.score.notes[i].pitch);
    }
    EXPECT_LT(left_top, right_bottom) << "tick " << tick;
  }
}

// Two lines a third apart in the two staves (43e's bars of thirds around B4): the hands would
// play inside each other, and one hand spans both, so it plays them all. Lines an octave apart,
// or close chords one hand cannot hold (six keys), stay in their staves.
TEST(HandAssignment, CrowdedLinesOneHandSpansGoToIt) {
  // Chords `left` and `right` struck together on two beats: how many notes left their staff's hand.
  const auto moved = [](const std::vector<int>& left, const std::vector<int>& right) {
    PianoScore s;
    for (const std::int64_t tick : {0, 480}) {
      for (const int pitch : left) s.add(pitch, tick, 480, 2);
      for (const int pitch : right) s.add(pitch, tick, 480, 1);
    }
    music::finalize_score(s.score);
    const HandAssignment a = assign_hands(s.score, test::model("default"));
    int count = 0;
    for (std::size_t i = 0; i < s.score.notes.size(); ++i) {
      const Hand staff = s.score.notes[i].staff == 1 ? Hand::right : Hand::left;
      if (a.hand[i] != staff) ++count;
    }
    return count;
  };
  {
    PianoScore s;
    const int left[] = {66, 67, 69, 71};   // F#4 G4 A4 B4
    const int right[] = {69, 71, 73, 74};  // A4 B4 C#5 D5
    for (int k = 0; k < 4; ++k) {
      s.add(left[k], k * 480, 480, 2);
      s.add(right[k], k * 480, 480, 1);
    }
    music::finalize_score(s.score);
    const HandAssignment a = assign_hands(s.score, test::model("default"));
    for (std::size_t i = 0; i < s.score.notes.size(); ++i) {
      EXPECT_EQ(a.hand[i], Hand::right) << s.score.notes[i].pitch;
      if (s.score.notes[i].staff == 2) {
        EXPECT_EQ(a.source[i], HandSource::crowded);
      }
    }
  }
  EXPECT_EQ(moved({67}, {71}), 2);          // G4 under B4: the right hand plays both
  EXPECT_EQ(moved({55}, {67}), 0);          // an octave apart: as written
  EXPECT_EQ(moved({55, 59, 62}, {64, 67, 71}), 0);  // six keys: no one hand holds them
}

TEST(HandAssignment, HandsAFileStatesAreKept) {
  PianoScore s;
  s.add(62, 0, 480, 1);
  s.add(83, 0, 480, 1);
  for (music::Note& n : s.score.notes) n.hand = Hand::right;
  music::finalize_score(s.score);
  const HandAssignment a = assign_hands(s.score, test::model("default"));
  EXPECT_EQ(s.hand_of(a, 62, 0), Hand::right);
  EXPECT_EQ(s.hand_of(a, 83, 0), Hand::right);
}

// Parts split automatically: a key one hand still holds is never passed by the other hand. The
// left hand holds E4 under the right hand's E5-G5-C6; the D4 that follows goes to the left hand
// (beside its E4), not to the right thumb under it (which alone would be nearer where the right
// hand was).
TEST(HandAssignment, AnAutomaticSplitNeverPassesAKeyTheOtherHandHolds) {
  PianoScore s;
  s.score.parts[0].staves = 1;
  s.add(64, 0, 1920, 0);
  s.add(76, 0, 1920, 0);
  s.add(79, 0, 1920, 0);
  s.add(84, 0, 1920, 0);
  s.add(62, 480, 240, 0);
  music::finalize_score(s.score);
  const HandAssignment a = assign_hands(s.score, test::model("default"));
  EXPECT_EQ(s.hand_of(a, 64, 0), Hand::left);
  EXPECT_EQ(s.hand_of(a, 76, 0), Hand::right);
  EXPECT_EQ(s.hand_of(a, 62, 480), Hand::left);
}

// Counts notes struck by one hand at or beyond a key the other hand holds (sounding 50 ms past
// the onset): the right hand at or below a held left key, the left at or above a held right key.
int passes_a_held_key(const music::Score& score, const HandAssignment& a) {
  int passes = 0;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    const music::Note& n = score.notes[i];
    if (a.source[i] != HandSource::automatic) continue;
    for (std::size_t j = 0; j < score.notes.size(); ++j) {
      const music::Note& h = score.notes[j];
      if (a.hand[j] == a.hand[i] || a.hand[j] == Hand::unknown) continue;
      if (!(h.onset_s < n.onset_s && h.offset_s > n.onset_s + 0.05)) continue;
      if (a.hand[i] == Hand::right ? n.pitch <= h.pitch : n.pitch >= h.pitch) ++passes;
    }
  }
  return passes;
}

// Third-party fugue and invention voices on separate tracks and parts: the automatic split
// gives no hand a key past one the other hand holds (bach_846's fugue gave the right thumb C4
// under the left thumb's held E4 at 148 s).
TEST(HandAssignment, ThirdPartyVoicesSplitWithoutPassingHeldKeys) {
  TUTTI_REQUIRE_TESTDATA();
  for (const char* file : {"midi/tonejs/bach_846.mid", "musicxml/pianoplayer/bach_invention4.xml",
                           "musicxml/pianoplayer/pachelbel_canon.xml"}) {
    auto score = music::load_score(tutti::test::testdata(file));
    ASSERT_TRUE(score.ok()) << score.error().message;
    const HandAssignment a = assign_hands(*score, test::model("default"));
    EXPECT_EQ(passes_a_held_key(*score, a), 0) << file;
  }
}

// A key both staves strike at once is one key: the hand with its other keys near it plays it.
TEST(HandAssignment, AKeyBothHandsStrikeAtOnceIsPlayedByOne) {
  PianoScore s;
  s.add(62, 0, 480, 1);  // the right-hand staff doubles the left hand's D4
  s.add(74, 0, 480, 1);
  s.add(50, 0, 480, 2);
  s.add(57, 0, 480, 2);
  s.add(62, 0, 480, 2);
  s.add(67, 480, 480, 1);  // and later strikes a G4 of its own
  s.add(67, 960, 480, 1);  // both staves on G4, the left hand's other keys nearer
  s.add(67, 960, 480, 2);
  s.add(64, 960, 480, 2);
  music::finalize_score(s.score);
  const HandAssignment a = assign_hands(s.score, test::model("default"));
  int d4_left = 0, g4_left = 0;
  for (std::size_t i = 0; i < s.score.notes.size(); ++i) {
    const music::Note& n = s.score.notes[i];
    if (n.pitch == 62) d4_left += a.hand[i] == Hand::left;
    if (n.pitch == 67 && n.onset_ticks == 960) g4_left += a.hand[i] == Hand::left;
  }
  EXPECT_EQ(d4_left, 2);  // near A3 and D3 of the left hand, one key of the right hand's
  EXPECT_EQ(g4_left, 2);
  EXPECT_EQ(s.hand_of(a, 67, 480), Hand::right);
  EXPECT_EQ(s.hand_of(a, 74, 0), Hand::right);
}

// The third-party sonata: after the assignment, no chord struck by one hand is wider than the
// hand spans where the other hand was free to help (the planner reports what is left).
TEST(HandAssignment, ScarlattisWideRightHandChordsAreShared) {
  TUTTI_REQUIRE_TESTDATA();
  auto score = music::load_score(tutti::test::testdata("musicxml/pianoplayer/scarlatti_k027.xml"));
  ASSERT_TRUE(score.ok()) << score.error().message;
  const HandAssignment a = assign_hands(*score, test::model("default"));
  int moved = 0;
  for (std::size_t i = 0; i < score->notes.size(); ++i) {
    if (a.source[i] != HandSource::reach) continue;
    ++moved;
    EXPECT_EQ(a.hand[i], Hand::left) << "note " << i;  // the right-hand staff gives, low notes
  }
  EXPECT_GT(moved, 0);
  auto plan = plan_score(*score, test::model("default"));
  ASSERT_TRUE(plan.ok()) << plan.error().message;
}

}  // namespace
}  // namespace tutti::fingering_planner
