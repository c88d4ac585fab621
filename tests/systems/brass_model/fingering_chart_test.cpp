// SPDX-License-Identifier: MIT
// The derived charts against standard fingering charts: the source's table (Horii 2018), the
// full primary charts of the B♭ trumpet and the tenor trombone, the F attachment, the double
// horn's sides, the 4-valve euphonium and tuba; alternates and their order; invariants.
#include <tutti/brass_model/fingering_chart.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "brass_fixture.hpp"

namespace tutti::brass_model {
namespace {

using test::instrument;
using test::key;
using test::names;
using test::standard;

TEST(FingeringChart, ReproducesTheSourceTable) {
  // Concert MIDI key → B♭ trumpet valves / trombone position (Horii 2018).
  const std::vector<std::tuple<int, const char*, const char*>> table = {
      {57, "2", "2"}, {59, "1-2-3", "4"}, {60, "1-3", "3"}, {62, "1-2", "1"},
      {64, "2", "2"}, {65, "open", "1"},  {67, "1-2", "2"}, {69, "2", "2"}};
  const Instrument& trumpet = instrument("trumpet_bb");
  const Instrument& trombone = instrument("trombone_tenor");
  for (const auto& [sounding, valves, position] : table) {
    EXPECT_EQ(standard(trumpet, trumpet.written(sounding)), valves) << sounding;
    EXPECT_EQ(standard(trombone, trombone.written(sounding)), position) << sounding;
  }
}

TEST(FingeringChart, BbTrumpetFullRangeIsTheStandardPrimaryChart) {
  // Written F#3..E6, the chart in every beginner's method book.
  const std::vector<std::pair<const char*, const char*>> chart = {
      {"F#3", "1-2-3"}, {"G3", "1-3"},  {"G#3", "2-3"},   {"A3", "1-2"},  {"A#3", "1"},
      {"B3", "2"},      {"C4", "open"}, {"C#4", "1-2-3"}, {"D4", "1-3"},  {"D#4", "2-3"},
      {"E4", "1-2"},    {"F4", "1"},    {"F#4", "2"},     {"G4", "open"}, {"G#4", "2-3"},
      {"A4", "1-2"},    {"A#4", "1"},   {"B4", "2"},      {"C5", "open"}, {"C#5", "1-2"},
      {"D5", "1"},      {"D#5", "2"},   {"E5", "open"},   {"F5", "1"},    {"F#5", "2"},
      {"G5", "open"},   {"G#5", "2-3"}, {"A5", "1-2"},    {"A#5", "1"},   {"B5", "2"},
      {"C6", "open"},   {"C#6", "1-2"}, {"D6", "1"},      {"D#6", "2"},   {"E6", "open"}};
  const Instrument& trumpet = instrument("trumpet_bb");
  ASSERT_EQ(int(chart.size()), key("E6") - key("F#3") + 1);
  EXPECT_LE(trumpet.lowest_written, key("F#3"));
  EXPECT_GE(trumpet.highest_written, key("E6"));
  EXPECT_EQ(trumpet.lowest_written, key("F#3"));  // nothing lower has a valve combination
  for (const auto& [pitch, valves] : chart) {
    EXPECT_EQ(standard(trumpet, key(pitch)), valves) << pitch;
  }
  // Bach's highest trumpet note in the test chorales, concert D6, is written E6.
  EXPECT_FALSE(trumpet.fingerings(trumpet.written(86)).empty());
}

TEST(FingeringChart, CTrumpetIsTheSameChartAtConcertPitch) {
  const Instrument& c = instrument("trumpet_c");
  const Instrument& bb = instrument("trumpet_bb");
  EXPECT_EQ(c.transposition_semitones, 0);
  EXPECT_EQ(bb.transposition_semitones, -2);
  for (int w = key("F#3"); w <= key("E6"); ++w) EXPECT_EQ(standard(c, w), standard(bb, w)) << w;
  // Concert D6 (Bach) on the C trumpet: written D6, valve 1 on the 10th partial.
  EXPECT_EQ(standard(c, c.written(86)), "1");
  EXPECT_EQ(c.fingerings(c.written(86)).front().partial, 10);
  // The C trumpet is the shorter tube (a whole tone higher).
  EXPECT_NEAR(bb.tube_length_mm / c.tube_length_mm, std::exp2(2.0 / 12.0), 1e-9);
}

TEST(FingeringChart, TenorTromboneFullRangeIsTheStandardPositionChart) {
  // Sounding E2..F5 (the trombone reads at pitch), the usual primary slide-position chart.
  const std::vector<std::pair<const char*, const char*>> chart = {
      {"E2", "7"},  {"F2", "6"}, {"F#2", "5"}, {"G2", "4"},  {"G#2", "3"}, {"A2", "2"},
      {"A#2", "1"}, {"B2", "7"}, {"C3", "6"},  {"C#3", "5"}, {"D3", "4"},  {"D#3", "3"},
      {"E3", "2"},  {"F3", "1"}, {"F#3", "5"}, {"G3", "4"},  {"G#3", "3"}, {"A3", "2"},
      {"A#3", "1"}, {"B3", "4"}, {"C4", "3"},  {"C#4", "2"}, {"D4", "1"},  {"D#4", "3"},
      {"E4", "2"},  {"F4", "1"}, {"F#4", "3"}, {"G4", "2"},  {"G#4", "3"}, {"A4", "2"},
      {"A#4", "1"}, {"B4", "4"}, {"C5", "3"},  {"C#5", "2"}, {"D5", "1"},  {"D#5", "3"},
      {"E5", "2"},  {"F5", "1"}};
  const Instrument& trombone = instrument("trombone_tenor");
  ASSERT_EQ(int(chart.size()), key("F5") - key("E2") + 1);
  EXPECT_EQ(trombone.transposition_semitones, 0);
  for (const auto& [pitch, position] : chart) {
    EXPECT_EQ(standard(trombone, key(pitch)), position) << pitch;
  }
  // F#4 and G4 are the flat 7th partial with the slide a little short; F#4's alternate is 5th.
  EXPECT_EQ(trombone.fingerings(key("F#4")).front().partial, 7);
  EXPECT_EQ(names(trombone, key("F#4")).at(1), "5");
  EXPECT_EQ(trombone.fingerings(key("G4")).front().partial, 7);
}

TEST(FingeringChart, TromboneFAttachment) {
  const Instrument& trombone = instrument("trombone_tenor");
  ASSERT_EQ(trombone.valves.size(), 1u);
  EXPECT_EQ(trombone.valves[0].name, "T");
  // The classic uses: C3 in T1 instead of 6th, B2 in T2 instead of 7th — the first alternates.
  EXPECT_EQ(names(trombone, key("C3")).at(1), "T1");
  EXPECT_EQ(names(trombone, key("B2")).at(1), "T2");
  EXPECT_EQ(names(trombone, key("A#2")).at(1), "T3");
  // It fills the gap below E2 (the slide on the longer F tube reaches T5 = C#2, not C2).
  EXPECT_EQ(standard(trombone, key("D#2")), "T3");
  EXPECT_EQ(standard(trombone, key("D2")), "T4");
  EXPECT_EQ(standard(trombone, key("C#2")), "T5");
  EXPECT_EQ(trombone.lowest_written, key("C#2"));
  // On the F tube positions lie further apart: T2 is out beyond the plain 2nd position.
  const Fingering& t2 = trombone.fingerings(key("B2"))[1];
  const Fingering& second = trombone.fingerings(key("A2")).front();
  EXPECT_GT(t2.slide_mm, second.slide_mm * 1.2f);
  EXPECT_NEAR(t2.slide_mm / second.slide_mm, std::exp2(5.0 / 12.0), 0.05);
}

TEST(FingeringChart, AlternatesAreListedInOrderOfPreference) {
  const Instrument& trumpet = instrument("trumpet_bb");
  using V = std::vector<std::string>;
  EXPECT_EQ(names(trumpet, key("A4")), (V{"1-2", "3"}));  // 1-2 by convention, 3 in tune
  EXPECT_EQ(names(trumpet, key("E4")), (V{"1-2", "3"}));
  EXPECT_EQ(names(trumpet, key("G#4")), (V{"2-3"}));
  EXPECT_EQ(names(trumpet, key("G4")), (V{"open", "1-3"}));
  EXPECT_EQ(names(trumpet, key("F#4")), (V{"2", "1-2-3"}));
  EXPECT_EQ(names(trumpet, key("D5")), (V{"1", "1-3"}));
  EXPECT_EQ(names(trumpet, key("E5")).at(1), "1-2");
  EXPECT_EQ(names(trumpet, key("D6")).at(1), "open");  // the 9th partial, kept for alternates
  const Instrument& trombone = instrument("trombone_tenor");
  EXPECT_EQ(names(trombone, key("D4")).at(1), "4");
  EXPECT_EQ(names(trombone, key("F4")).at(1), "6");
  EXPECT_EQ(names(trombone, key("A#3")).at(1), "5");
  EXPECT_EQ(names(trombone, key("B3")).at(1), "7");
  EXPECT_EQ(names(trombone, key("C4")).at(1), "6");
  EXPECT_EQ(names(trombone, key("A4")).at(1), "4");
  // Plain slide positions before the trigger.
  for (int w = key("E2"); w <= key("F5"); ++w) {
    bool trigger_seen = false;
    for (const Fingering& f : trombone.fingerings(w)) {
      if (f.valves != 0) trigger_seen = true;
      EXPECT_FALSE(trigger_seen && f.valves == 0) << music::pitch_name(w);
    }
  }
}

TEST(FingeringChart, TheFlatSeventhPartialIsNotUsedWithValvesNorInFirstPosition) {
  for (const Instrument& i : test::shipped()) {
    for (int w = i.lowest_written; w <= i.highest_written; ++w) {
      for (const Fingering& f : i.fingerings(w)) {
        if (i.mechanism == Mechanism::valves) {
          EXPECT_NE(f.partial % 7, 0) << i.id << " " << music::pitch_name(w);
          EXPECT_NE(f.partial, 11) << i.id << " " << music::pitch_name(w);
        } else if (f.partial == 7 || f.partial == 14) {
          EXPECT_GT(f.position, 1) << i.id << " " << music::pitch_name(w);
          EXPECT_NEAR(f.cents, -31.2f, 0.1f);
        }
      }
    }
  }
  // A♭4 on the trombone: not the flat 7th partial in 1st but 3rd position on the 8th.
  const Instrument& trombone = instrument("trombone_tenor");
  EXPECT_EQ(standard(trombone, key("G#4")), "3");
  EXPECT_EQ(trombone.fingerings(key("G#4")).front().partial, 8);
}

TEST(FingeringChart, DoubleHornFSideLowBbSideHigh) {
  const Instrument& horn = instrument("horn_double");
  EXPECT_EQ(horn.transposition_semitones, -7);
  const std::vector<std::pair<const char*, const char*>> chart = {
      // F side (no thumb) up to written G4.
      {"F#2", "1-2-3"},
      {"C3", "open"},
      {"G3", "open"},
      {"A3", "1-2"},
      {"C4", "open"},
      {"D4", "1"},
      {"E4", "open"},
      {"F4", "1"},
      {"F#4", "2"},
      {"G4", "open"},
      // B♭ side (thumb) from G#4, avoiding its flat 5th partial (A4) and its octave (A5).
      {"G#4", "T-2-3"},
      {"A4", "T-1-2"},
      {"A#4", "T-1"},
      {"B4", "T-2"},
      {"C5", "T"},
      {"D5", "T-1-2"},
      {"E5", "T-2"},
      {"F5", "T"},
      {"G5", "T"},
      {"A5", "T-1-2"},
      {"C6", "T"}};
  for (const auto& [pitch, valves] : chart) {
    EXPECT_EQ(standard(horn, key(pitch)), valves) << pitch;
  }
  for (int w = horn.lowest_written; w <= horn.highest_written; ++w) {
    const bool thumb = (horn.fingerings(w).front().valves & 0b1000) != 0;
    EXPECT_EQ(thumb, w >= key("G#4")) << music::pitch_name(w);
  }
  // The horn's open series goes up to the 16th partial (written C6 on the F side).
  const auto c6 = names(horn, key("C6"));
  EXPECT_NE(std::find(c6.begin(), c6.end(), "open"), c6.end());
  EXPECT_EQ(horn.fingerings(key("C6")).front().partial, 12);
}

TEST(FingeringChart, FourValveEuphoniumAndTuba) {
  // The 4th valve replaces 1-3 and 2-4 replaces 1-2-3; the 9th partial is for alternates.
  const std::vector<std::pair<const char*, const char*>> euphonium = {
      {"E2", "2-4"},   {"F2", "4"},   {"G2", "1-2"},  {"A#2", "open"}, {"B2", "2-4"},
      {"C3", "4"},     {"D3", "1-2"}, {"F3", "open"}, {"F#3", "2-3"},  {"A#3", "open"},
      {"B3", "1-2"},   {"C4", "1"},   {"D4", "open"}, {"F4", "open"},  {"G#4", "1"},
      {"A#4", "open"}, {"B4", "1-2"}, {"C5", "1"},    {"D5", "open"},  {"F5", "open"}};
  const Instrument& euph = instrument("euphonium");
  const Instrument& tuba = instrument("tuba");
  EXPECT_EQ(euph.valves.size(), 4u);
  EXPECT_EQ(tuba.valves.size(), 4u);
  for (const auto& [pitch, valves] : euphonium) {
    EXPECT_EQ(standard(euph, key(pitch)), valves) << pitch;
    // The B♭B♭ tuba plays the same fingerings an octave lower.
    EXPECT_EQ(standard(tuba, key(pitch) - 12), valves) << pitch << " an octave down";
  }
  // Non-compensating: 1-3 is the sharp alternate of 4.
  const auto c3 = euph.fingerings(key("C3"));
  ASSERT_GE(c3.size(), 2u);
  EXPECT_EQ(fingering_name(euph, c3[1]), "1-3");
  EXPECT_GT(c3[1].cents, c3[0].cents + 20.0f);
}

TEST(FingeringChart, TuningBeforeCorrectionFollowsThePhysics) {
  const Instrument& trumpet = instrument("trumpet_bb");
  // Written D4 (1-3 on the 3rd partial) is well sharp; A4 with valve 3 is in tune.
  EXPECT_GT(trumpet.fingerings(key("D4")).front().cents, 25.0f);
  EXPECT_NEAR(trumpet.fingerings(key("A4"))[1].cents, 0.0f, 0.5f);
  // E5 open is the flat 5th partial.
  EXPECT_NEAR(trumpet.fingerings(key("E5")).front().cents, -13.7f, 0.2f);
  // Trombone D4 in 1st (5th partial): the slide cannot go shorter, the lips take 14 cents.
  const Fingering& d4 = instrument("trombone_tenor").fingerings(key("D4")).front();
  EXPECT_EQ(d4.slide_mm, 0.0f);
  EXPECT_NEAR(d4.cents, -13.7f, 0.2f);
}

TEST(FingeringChart, EveryChartIsWellFormed) {
  for (const Instrument& i : test::shipped()) {
    ASSERT_EQ(int(i.chart_begin.size()), i.highest_written - i.lowest_written + 2) << i.id;
    EXPECT_EQ(i.chart_begin.back(), int(i.chart.size())) << i.id;
    EXPECT_TRUE(i.fingerings(i.lowest_written - 1).empty());
    EXPECT_TRUE(i.fingerings(i.highest_written + 1).empty());
    for (int w = i.lowest_written; w <= i.highest_written; ++w) {
      const auto list = i.fingerings(w);
      ASSERT_FALSE(list.empty()) << i.id << " " << music::pitch_name(w);
      std::map<std::string, int> seen;
      for (std::size_t r = 0; r < list.size(); ++r) {
        const Fingering& f = list[r];
        EXPECT_EQ(f.rank, r);
        EXPECT_LE(std::abs(f.cents), 60.0f);
        EXPECT_EQ(++seen[fingering_name(i, f)], 1) << i.id << " " << fingering_name(i, f);
        if (i.mechanism == Mechanism::slide) {
          EXPECT_GE(f.position, 1);
          EXPECT_LE(f.position, i.positions);
          EXPECT_GE(f.slide_mm, 0.0f);
          EXPECT_LE(f.slide_mm, float(i.slide_length_mm));
        } else {
          EXPECT_EQ(f.position, 0);
          EXPECT_EQ(f.slide_mm, 0.0f);
        }
      }
    }
  }
}

TEST(FingeringChart, SlideExtensionGrowsWithPosition) {
  const Instrument& trombone = instrument("trombone_tenor");
  EXPECT_EQ(trombone.positions, 7);
  EXPECT_NEAR(trombone.slide_length_mm, 609.5, 1.0);
  // The 2nd partial, no trigger: positions 1..7 play B♭2 down to E2.
  float previous = -1.0f;
  for (int p = 1; p <= 7; ++p) {
    const Fingering& f = trombone.fingerings(key("A#2") - (p - 1)).front();
    EXPECT_EQ(f.position, p);
    EXPECT_EQ(f.partial, 2);
    EXPECT_GT(f.slide_mm, previous);
    previous = f.slide_mm;
  }
}

TEST(FingeringChart, NamesWithPartials) {
  const Instrument& trumpet = instrument("trumpet_bb");
  EXPECT_EQ(fingering_name(trumpet, trumpet.fingerings(key("D4")).front(), true),
            "1-3 (partial 3)");
  const Instrument& trombone = instrument("trombone_tenor");
  EXPECT_EQ(fingering_name(trombone, trombone.fingerings(key("C3"))[1], true), "T1 (partial 3)");
}

}  // namespace
}  // namespace tutti::brass_model
