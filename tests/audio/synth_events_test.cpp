// SPDX-License-Identifier: MIT
// Scores -> synthesizer events (audio/synth_events.hpp) on the project's quartet and third-party
// MIDI files: channels, programs, block-aligned frames, tempo factor, start time, pedal.
#include <tutti/audio/synth_events.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include <tutti/music/load_score.hpp>
#include "testdata.hpp"

namespace tutti::audio {
namespace {

music::Score load(const std::filesystem::path& path) {
  auto score = music::load_score(path);
  EXPECT_TRUE(score) << score.error().message;
  return score ? std::move(*score) : music::Score{};
}

std::filesystem::path quartet() {
  return std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "music" / "quartet.musicxml";
}

TEST(SynthTimeline, EveryQuartetNoteStartsAndStopsOnItsPartsChannelWithinHalfABlock) {
  const music::Score score = load(quartet());
  ASSERT_EQ(score.parts.size(), 4u);
  const music::Score* scores[] = {&score};
  auto timeline = build_synth_timeline(scores, {});
  ASSERT_TRUE(timeline) << timeline.error().message;
  EXPECT_EQ(timeline->channel_count, 16);
  std::map<int, int> program_of_channel;
  std::size_t ons = 0;
  std::int64_t previous = 0;
  for (const SynthEvent& e : timeline->events) {
    EXPECT_EQ(e.frame % kSynthBlockFrames, 0);
    EXPECT_GE(e.frame, previous);
    previous = e.frame;
    if (e.kind == SynthEventKind::program) program_of_channel[e.channel] = e.data1;
    if (e.kind != SynthEventKind::note_on) continue;
    ++ons;
    const music::Note& note = score.notes[static_cast<std::size_t>(e.note)];
    EXPECT_EQ(e.channel, note.part);  // parts 0..3 on channels 0..3
    EXPECT_EQ(e.data1, note.pitch);
    EXPECT_LE(std::abs(static_cast<double>(e.frame) - note.onset_s * 48000.0), 32.0);
  }
  EXPECT_EQ(ons, score.notes.size());
  ASSERT_EQ(program_of_channel.size(), 4u);
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(program_of_channel[c], score.parts[static_cast<std::size_t>(c)].program);
  }
  EXPECT_GE(timeline->end_frame,
            static_cast<std::int64_t>(score.notes.back().offset_s * 48000.0) - 32);
}

TEST(SynthTimeline, HalfTempoDoublesEveryTimeAndStartShiftsThem) {
  const music::Score score = load(quartet());
  const music::Score* scores[] = {&score};
  auto normal = build_synth_timeline(scores, {});
  TimelineOptions slow;
  slow.tempo_factor = 0.5;
  auto half = build_synth_timeline(scores, slow);
  ASSERT_TRUE(normal && half);
  ASSERT_EQ(normal->events.size(), half->events.size());
  for (std::size_t i = 0; i < normal->events.size(); ++i) {
    EXPECT_NEAR(static_cast<double>(half->events[i].frame),
                2.0 * static_cast<double>(normal->events[i].frame), 64.0);
  }
  TimelineOptions later;
  later.start_s = 10.0;
  auto from_ten = build_synth_timeline(scores, later);
  ASSERT_TRUE(from_ten);
  std::size_t expected_ons = 0;
  for (const music::Note& n : score.notes) expected_ons += n.onset_s >= 10.0 ? 1 : 0;
  std::size_t ons = 0;
  for (const SynthEvent& e : from_ten->events) {
    EXPECT_GE(e.frame, 0);
    if (e.kind != SynthEventKind::note_on) continue;
    ++ons;
    const double onset = score.notes[static_cast<std::size_t>(e.note)].onset_s;
    EXPECT_LE(std::abs(static_cast<double>(e.frame) - (onset - 10.0) * 48000.0), 32.0);
  }
  EXPECT_EQ(ons, expected_ons);
  EXPECT_GT(ons, 0u);
}

TEST(SynthTimeline, DamperPedalBecomesControllerSixtyFour) {
  TUTTI_REQUIRE_TESTDATA();
  const music::Score score =
      load(std::filesystem::path(TUTTI_TESTDATA_DIR) / "midi/jazz-soft/test-control-40-damper.mid");
  ASSERT_FALSE(score.pedal_spans.empty());
  const music::Score* scores[] = {&score};
  auto timeline = build_synth_timeline(scores, {});
  ASSERT_TRUE(timeline);
  int downs = 0;
  int ups = 0;
  for (const SynthEvent& e : timeline->events) {
    if (e.kind != SynthEventKind::control || e.data1 != 64) continue;
    (e.data2 == 127 ? downs : ups) += 1;
  }
  EXPECT_EQ(downs, static_cast<int>(score.pedal_spans.size()));
  EXPECT_EQ(ups, downs);
}

TEST(SynthTimeline, ManyPartsSkipThePercussionChannels) {
  music::Score score;
  score.source = "many.mid";
  for (int p = 0; p < 20; ++p) {
    music::Part part;
    part.program = p;
    score.parts.push_back(part);
  }
  music::Part drums;
  drums.percussion = true;
  score.parts.push_back(drums);
  const music::Score* scores[] = {&score};
  auto timeline = build_synth_timeline(scores, {});
  ASSERT_TRUE(timeline);
  EXPECT_EQ(timeline->channel_count, 32);
  std::map<int, int> program_of_channel;
  for (const SynthEvent& e : timeline->events) {
    if (e.kind == SynthEventKind::program) program_of_channel[e.channel] = e.data1;
  }
  EXPECT_EQ(program_of_channel.size(), 20u);
  EXPECT_EQ(program_of_channel.count(9), 0u);
  EXPECT_EQ(program_of_channel.count(25), 0u);
  EXPECT_EQ(program_of_channel[10], 9);  // the tenth melodic part, after channel 9 was skipped
}

TEST(SynthTimeline, BadOptionsAreErrors) {
  const music::Score score = load(quartet());
  const music::Score* scores[] = {&score};
  TimelineOptions o;
  o.tempo_factor = 0.0;
  auto zero = build_synth_timeline(scores, o);
  ASSERT_FALSE(zero);
  EXPECT_EQ(zero.error().message, "audio: tempo factor must be in [0.1, 4]");
  o = {};
  o.sample_rate = 100;
  EXPECT_FALSE(build_synth_timeline(scores, o));
  o = {};
  o.tempo_factor = std::nan("");
  EXPECT_FALSE(build_synth_timeline(scores, o));
}

}  // namespace
}  // namespace tutti::audio
