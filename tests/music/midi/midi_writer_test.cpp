// SPDX-License-Identifier: MIT
// Writer tests: the bytes it produces, and round trips (write -> read) of hand-made scores.

#include <tutti/music/midi/midi_writer.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <tutti/music/midi/midi_reader.hpp>
#include "score_compare.hpp"
#include "smf_bytes.hpp"
#include "testdata.hpp"

namespace tutti::music {
namespace {

Note make_note(int part, int channel, int pitch, std::int64_t on, std::int64_t off,
               int velocity = 80) {
  Note note;
  note.part = part;
  note.channel = channel;
  note.pitch = pitch;
  note.onset_ticks = on;
  note.offset_ticks = off;
  note.velocity = velocity;
  return note;
}

Part make_part(std::string name, int channel, int program, bool percussion = false) {
  Part part;
  part.name = std::move(name);
  part.channel = channel;
  part.program = program;
  part.percussion = percussion;
  return part;
}

// A little of everything the writer must keep.
Score hand_made_score() {
  Score score;
  score.tempo_map = TempoMap::with_ticks_per_quarter(480);
  score.tempo_map.set_tempo(0, 600000);
  score.tempo_map.set_tempo(1920, 400000);
  score.parts = {make_part("Piano", 0, 0), make_part("Drums", 9, 0, true),
                 make_part("Violin", 3, 40)};
  score.notes = {
      make_note(0, 0, 60, 0, 480),  // two overlapping notes of one key, first in first out
      make_note(0, 0, 60, 240, 720),
      make_note(0, 0, 64, 0, 480),  // two back-to-back notes of one key
      make_note(0, 0, 64, 480, 960),
      make_note(0, 0, 62, 960, 960),   // zero length
      make_note(0, 0, 62, 960, 1200),  // starts with it
      make_note(1, 9, 36, 0, 120, 127),
      make_note(2, 3, 67, 480, 1440, 90),
  };
  score.notes.back().release_velocity = 20;
  PedalSpan pedal;
  pedal.part = 0;
  pedal.onset_ticks = 0;
  pedal.offset_ticks = 900;
  score.pedal_spans.push_back(pedal);
  pedal.onset_ticks = 900;  // a pedal change: lifted and pressed at once
  pedal.offset_ticks = 1800;
  score.pedal_spans.push_back(pedal);
  score.time_signatures = {TimeSignature{0, 0.0, 4, 4}, TimeSignature{1920, 0.0, 3, 4}};
  score.key_signatures = {KeySignature{0, 0.0, 2, false}, KeySignature{1920, 0.0, -3, true}};
  score.texts = {TextEvent{0, 0.0, TextKind::marker, -1, "A"},
                 TextEvent{1920, 0.0, TextKind::marker, -1, "B"}};
  score.end_ticks = 3840;
  finalize_score(score);
  return score;
}

Score write_and_read(const Score& score) {
  auto read = read_midi(write_midi(score), "written.mid");
  EXPECT_TRUE(read.ok()) << read.error().message;
  return read.ok() ? std::move(read).value() : Score{};
}

TEST(MidiWriter, HeaderIsFormat1WithTheScoresResolution) {
  const auto file = write_midi(hand_made_score());
  ASSERT_GE(file.size(), 14u);
  EXPECT_EQ(test::Bytes(file.begin(), file.begin() + 14),
            test::bytes({'M', 'T', 'h', 'd', 0, 0, 0, 6, 0, 1, 0, 4, 0x01, 0xE0}));
}

TEST(MidiWriter, HandMadeScoreSurvivesARoundTrip) {
  const Score score = hand_made_score();
  const Score back = write_and_read(score);
  test::expect_same_music(score, back);
  std::vector<std::string> markers;
  for (const TextEvent& text : back.texts) {
    if (text.kind == TextKind::marker) markers.push_back(text.text);
  }
  EXPECT_EQ(markers, (std::vector<std::string>{"A", "B"}));
  ASSERT_EQ(back.parts.size(), 3u);
  EXPECT_EQ(back.parts[2].name, "Violin");
  for (const Note& note : back.notes) {
    EXPECT_EQ(note.release_velocity, note.part == 2 ? 20 : 64);
  }
}

TEST(MidiWriter, ReadScoreSurvivesARoundTripTwice) {
  const Score first = write_and_read(hand_made_score());
  const Score second = write_and_read(first);
  test::expect_same_music(first, second);
  for (std::size_t i = 0; i < first.parts.size(); ++i) {
    EXPECT_EQ(first.parts[i].id, second.parts[i].id);  // same layout once written by us
  }
}

TEST(MidiWriter, PartsWithoutAChannelGetOne) {
  Score score;
  score.parts = {make_part("Flute", -1, 73), make_part("Kit", -1, 0, true),
                 make_part("Oboe", -1, 68)};
  score.notes = {make_note(0, 0, 72, 0, 480), make_note(1, 0, 38, 0, 480),
                 make_note(2, 0, 74, 0, 480)};
  finalize_score(score);
  const Score back = write_and_read(score);
  ASSERT_EQ(back.parts.size(), 3u);
  EXPECT_EQ(back.parts[0].channel, 0);
  EXPECT_EQ(back.parts[1].channel, 9);
  EXPECT_TRUE(back.parts[1].percussion);
  EXPECT_EQ(back.parts[2].channel, 1);
  EXPECT_EQ(back.parts[2].program, 68);
  EXPECT_EQ(back.parts[2].name, "Oboe");
}

TEST(MidiWriter, SmpteScoreIsWrittenAt480PpqKeepingSeconds) {
  Score score;
  score.tempo_map = TempoMap::with_smpte(25, 40);  // 1000 ticks per second
  score.tempo_map.set_tempo(1000, 250000);
  score.parts = {make_part("Piano", 0, 0)};
  score.notes = {make_note(0, 0, 60, 0, 1500), make_note(0, 0, 62, 1500, 2000),
                 make_note(0, 0, 64, 2250, 2999)};
  score.end_ticks = 3000;
  finalize_score(score);
  const Score back = write_and_read(score);
  EXPECT_FALSE(back.tempo_map.is_smpte());
  EXPECT_EQ(back.tempo_map.ticks_per_quarter(), 480);
  ASSERT_EQ(back.notes.size(), score.notes.size());
  // One tick at 480 PPQ is at most ~1 ms here; rounding to ticks costs half of that.
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    EXPECT_NEAR(back.notes[i].onset_s, score.notes[i].onset_s, 6e-4);
    EXPECT_NEAR(back.notes[i].offset_s, score.notes[i].offset_s, 6e-4);
  }
  EXPECT_NEAR(back.duration_s(), 3.0, 6e-4);
}

TEST(MidiWriter, GapsBeyondTheLongestDeltaTimeAreBridged) {
  Score score;
  score.tempo_map = TempoMap::with_ticks_per_quarter(1);
  score.parts = {make_part("", 0, 0)};
  const std::int64_t far = 0x0FFFFFFFLL * 2 + 5;
  score.notes = {make_note(0, 0, 60, 0, 1), make_note(0, 0, 62, far, far + 1)};
  finalize_score(score);
  const Score back = write_and_read(score);
  test::expect_same_music(score, back);
}

TEST(MidiWriter, VelocityZeroIsWrittenAsOneSoItStaysANote) {
  Score score;
  score.parts = {make_part("", 0, 0)};
  score.notes = {make_note(0, 0, 60, 0, 480, 0)};
  finalize_score(score);
  const Score back = write_and_read(score);
  ASSERT_EQ(back.notes.size(), 1u);
  EXPECT_EQ(back.notes[0].velocity, 1);
  EXPECT_EQ(back.notes[0].offset_ticks, 480);
}

TEST(MidiWriter, WritesFilesAtomically) {
  const auto dir = test::unique_temp_path("midi_writer");
  std::filesystem::create_directories(dir);
  const auto path = dir / "song.mid";
  const Score score = hand_made_score();
  const Status status = write_midi_file(score, path);
  ASSERT_TRUE(status.ok()) << status.error().message;
  auto back = read_midi_file(path);
  ASSERT_TRUE(back.ok()) << back.error().message;
  test::expect_same_music(score, *back);
  std::filesystem::remove_all(dir);
}

TEST(MidiWriter, UnwritableFolderIsAnError) {
  const Status status = write_midi_file(hand_made_score(), "/nonexistent/dir/song.mid");
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("/nonexistent/dir/song.mid"), std::string::npos);
}

}  // namespace
}  // namespace tutti::music
