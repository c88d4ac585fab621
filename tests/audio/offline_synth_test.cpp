// SPDX-License-Identifier: MIT
// FluidSynth offline rendering (audio/offline_synth.hpp) with Debian's General MIDI sound font:
// a note sounds from its frame on and not before, the same timeline gives the same samples, and
// a missing or broken sound font is a clear error.
#include <tutti/audio/offline_synth.hpp>

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <tutti/audio/sound_font.hpp>
#include <tutti/music/load_score.hpp>

namespace tutti::audio {
namespace {

// One part (GM program), one note of `pitch` from onset to offset seconds.
music::Score one_note(int program, int pitch, double onset_s, double offset_s) {
  music::Score score;
  score.source = "one_note";
  music::Part part;
  part.program = program;
  score.parts.push_back(part);
  music::Note note;
  note.pitch = pitch;
  note.onset_s = onset_s;
  note.offset_s = offset_s;
  note.velocity = 100;
  score.notes.push_back(note);
  return score;
}

std::int64_t first_audible_frame(const AudioBuffer& audio, int threshold) {
  for (std::int64_t f = 0; f < audio.frames(); ++f) {
    const auto i = static_cast<std::size_t>(f) * 2;
    if (std::abs(audio.samples[i]) > threshold || std::abs(audio.samples[i + 1]) > threshold) {
      return f;
    }
  }
  return -1;
}

double rms(const AudioBuffer& audio, std::int64_t from, std::int64_t to) {
  double sum = 0.0;
  for (std::int64_t f = from; f < to; ++f) {
    const double v = audio.samples[static_cast<std::size_t>(f) * 2];
    sum += v * v;
  }
  return std::sqrt(sum / static_cast<double>(std::max<std::int64_t>(1, to - from)));
}

class OfflineSynthTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto font = find_sound_font();
    ASSERT_TRUE(font) << font.error().message;
    font_ = *font;
  }
  std::filesystem::path font_;
};

TEST_F(OfflineSynthTest, ANoteSoundsFromItsFrameOnAndNotBefore) {
  // 0.5 s at 48 kHz is frame 24000, a block boundary.
  const music::Score score = one_note(0, 60, 0.5, 1.0);
  const music::Score* scores[] = {&score};
  auto timeline = build_synth_timeline(scores, {});
  ASSERT_TRUE(timeline);
  OfflineSynthOptions options;
  options.sound_font = font_;
  auto audio = render_timeline(*timeline, options);
  ASSERT_TRUE(audio) << audio.error().message;
  EXPECT_EQ(audio->sample_rate, 48000);
  EXPECT_EQ(audio->frames(), timeline->end_frame + 96000);
  const std::int64_t first = first_audible_frame(*audio, 0);
  EXPECT_GE(first, 24000);
  EXPECT_LT(first, 24000 + 64) << "the piano's attack starts within its block";
  // Sounding while held, quieter long after the release.
  EXPECT_GT(rms(*audio, 24000, 48000), 300.0);
  EXPECT_LT(rms(*audio, 48000 + 72000, 48000 + 96000), rms(*audio, 24000, 48000) / 20.0);
}

TEST_F(OfflineSynthTest, TheQuartetRendersTheSameSamplesTwice) {
  auto score = music::load_score(std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "music" /
                                 "quartet.musicxml");
  ASSERT_TRUE(score) << score.error().message;
  const music::Score* scores[] = {&*score};
  TimelineOptions window;
  window.start_s = 4.0;
  auto timeline = build_synth_timeline(scores, window);
  ASSERT_TRUE(timeline);
  OfflineSynthOptions options;
  options.sound_font = font_;
  options.frames = 48000 * 4;
  auto a = render_timeline(*timeline, options);
  auto b = render_timeline(*timeline, options);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->samples, b->samples);
  EXPECT_GT(rms(*a, 0, a->frames()), 500.0) << "four brass players are not silent";
  std::size_t clipped = 0;
  for (std::int16_t s : a->samples) clipped += (s == 32767 || s == -32767) ? 1 : 0;
  EXPECT_LT(clipped, a->samples.size() / 10000);
}

TEST_F(OfflineSynthTest, MissingOrBrokenSoundFontsAreErrors) {
  auto missing = find_sound_font("/nonexistent/font.sf2");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().message,
            "/nonexistent/font.sf2: no such sound font (given with --soundfont)");
  const auto broken = std::filesystem::temp_directory_path() /
                      ("tutti-broken-" + std::to_string(getpid()) + ".sf2");
  std::ofstream(broken) << "RIFF this is not a sound font";
  const music::Score score = one_note(0, 60, 0.0, 0.1);
  const music::Score* scores[] = {&score};
  auto timeline = build_synth_timeline(scores, {});
  ASSERT_TRUE(timeline);
  OfflineSynthOptions options;
  options.sound_font = broken;
  auto audio = render_timeline(*timeline, options);
  std::filesystem::remove(broken);
  ASSERT_FALSE(audio);
  EXPECT_NE(audio.error().message.find(broken.string() + ": not a sound font"), std::string::npos)
      << audio.error().message;
}

}  // namespace
}  // namespace tutti::audio
