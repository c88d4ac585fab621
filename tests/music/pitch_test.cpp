// SPDX-License-Identifier: MIT
#include <tutti/music/pitch.hpp>

#include <gtest/gtest.h>

namespace tutti::music {
namespace {

TEST(PitchTest, ParsesSpelledNames) {
  EXPECT_EQ(parse_pitch_name("C4"), 60);
  EXPECT_EQ(parse_pitch_name("A4"), 69);
  EXPECT_EQ(parse_pitch_name("F#5"), 78);
  EXPECT_EQ(parse_pitch_name("Bb3"), 58);
  EXPECT_EQ(parse_pitch_name("Ebb2"), 38);
  EXPECT_EQ(parse_pitch_name("Cx4"), 62);
  EXPECT_EQ(parse_pitch_name("B#3"), 60);
  EXPECT_EQ(parse_pitch_name("Cb4"), 59);
  EXPECT_EQ(parse_pitch_name("C-1"), 0);
  EXPECT_EQ(parse_pitch_name("G9"), 127);
  EXPECT_EQ(parse_pitch_name("a0"), 21);
}

TEST(PitchTest, RejectsGarbageAndOutOfRange) {
  for (const char* bad : {"", "H4", "C", "4", "C4x", "G#9", "Cb-1", "C 4", "C99999999999"}) {
    EXPECT_FALSE(parse_pitch_name(bad).has_value()) << bad;
  }
}

TEST(PitchTest, NamesRoundTrip) {
  for (int key = 0; key <= 127; ++key) EXPECT_EQ(parse_pitch_name(pitch_name(key)), key);
  EXPECT_EQ(pitch_name(60), "C4");
  EXPECT_EQ(pitch_name(61), "C#4");
  EXPECT_EQ(pitch_name(21), "A0");
}

TEST(PitchTest, BlackKeys) {
  int black = 0;
  for (int key = 60; key < 72; ++key) black += is_black_key(key) ? 1 : 0;
  EXPECT_EQ(black, 5);
  EXPECT_TRUE(is_black_key(61));
  EXPECT_FALSE(is_black_key(64));
}

TEST(PitchTest, MidiKeyFromStepAlterOctave) {
  EXPECT_EQ(midi_key('G', 0, 2), 43);
  EXPECT_EQ(midi_key('C', 1, 7), 97);
  EXPECT_FALSE(midi_key('X', 0, 4).has_value());
  EXPECT_FALSE(midi_key('C', 0, 11).has_value());
}

}  // namespace
}  // namespace tutti::music
