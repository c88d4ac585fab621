// SPDX-License-Identifier: MIT
#include <tutti/music/score.hpp>

#include <gtest/gtest.h>

namespace tutti::music {
namespace {

Note make_note(int pitch, std::int64_t on, std::int64_t off) {
  Note n;
  n.pitch = pitch;
  n.onset_ticks = on;
  n.offset_ticks = off;
  return n;
}

TEST(ScoreTest, FinalizeSortsAndDerivesTimes) {
  Score score;
  score.tempo_map = TempoMap::with_ticks_per_quarter(100);
  score.tempo_map.set_tempo(200, 1'000'000.0);
  score.parts.push_back(Part{});
  score.notes = {make_note(64, 200, 300), make_note(60, 0, 100), make_note(55, 0, 250)};
  finalize_score(score);
  ASSERT_EQ(score.notes.size(), 3u);
  EXPECT_EQ(score.notes[0].pitch, 55);
  EXPECT_EQ(score.notes[1].pitch, 60);
  EXPECT_EQ(score.notes[2].pitch, 64);
  EXPECT_DOUBLE_EQ(score.notes[1].offset_s, 0.5);
  EXPECT_DOUBLE_EQ(score.notes[0].offset_s, 1.5);
  EXPECT_DOUBLE_EQ(score.notes[2].onset_s, 1.0);
  EXPECT_DOUBLE_EQ(score.notes[2].offset_beats, 3.0);
  EXPECT_EQ(score.end_ticks, 300);
  EXPECT_DOUBLE_EQ(score.duration_s(), 2.0);
}

TEST(ScoreTest, EndCoversLaterEventsAndPedals) {
  Score score;
  score.parts.push_back(Part{});
  score.notes = {make_note(60, 0, 480)};
  score.end_ticks = 1920;
  score.pedal_spans.push_back(PedalSpan{0, 100, 2400, 0, 0});
  finalize_score(score);
  EXPECT_EQ(score.end_ticks, 2400);
  EXPECT_DOUBLE_EQ(score.pedal_spans[0].offset_s, 2.5);
}

TEST(ScoreTest, NegativeLengthIsClampedToZero) {
  Score score;
  score.parts.push_back(Part{});
  score.notes = {make_note(60, 500, 100)};
  finalize_score(score);
  EXPECT_EQ(score.notes[0].offset_ticks, 500);
  EXPECT_DOUBLE_EQ(score.notes[0].offset_s, score.notes[0].onset_s);
}

}  // namespace
}  // namespace tutti::music
