// The onset detector (audio/onset_detection.hpp) on sounds whose onsets are known by
// construction: synthetic tone bursts (instant and ramped attacks, chords, vibrato) and single
// FluidSynth notes of the GM programs the demos use, placed at known frames.
#include "audio/onset_detection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "audio/sound_font.hpp"
#include "audio/synth_events.hpp"

namespace tutti::audio {
namespace {

constexpr int kRate = 48000;

struct Tone {
  double start_s = 0.0;
  double end_s = 0.0;
  double hz = 440.0;
  double amplitude = 0.3;
  double attack_s = 0.0;       // linear rise
  double vibrato_hz = 0.0;     // frequency modulation rate
  double vibrato_cents = 0.0;  // and depth
};

AudioBuffer mix(const std::vector<Tone>& tones, double length_s) {
  AudioBuffer audio;
  audio.sample_rate = kRate;
  audio.channels = 2;
  const auto frames = static_cast<std::size_t>(length_s * kRate);
  std::vector<double> sum(frames, 0.0);
  for (const Tone& tone : tones) {
    double phase = 0.0;
    for (std::size_t i = 0; i < frames; ++i) {
      const double t = static_cast<double>(i) / kRate;
      if (t < tone.start_s || t >= tone.end_s) continue;
      const double since = t - tone.start_s;
      double envelope = tone.attack_s > 0.0 ? std::min(1.0, since / tone.attack_s) : 1.0;
      envelope *= std::min(1.0, (tone.end_s - t) / 0.02);  // a 20 ms release, no click
      const double cents =
          tone.vibrato_cents * std::sin(2.0 * std::numbers::pi * tone.vibrato_hz * since);
      phase += 2.0 * std::numbers::pi * tone.hz * std::pow(2.0, cents / 1200.0) / kRate;
      // A few harmonics, like an instrument.
      double v = 0.0;
      for (int h = 1; h <= 4; ++h) v += std::sin(h * phase) / h;
      sum[i] += tone.amplitude * envelope * v * 0.5;
    }
  }
  audio.samples.resize(frames * 2);
  for (std::size_t i = 0; i < frames; ++i) {
    const auto s = static_cast<std::int16_t>(std::lround(std::clamp(sum[i], -1.0, 1.0) * 32767.0));
    audio.samples[2 * i] = s;
    audio.samples[2 * i + 1] = s;
  }
  return audio;
}

std::vector<double> times_of(const std::vector<Onset>& onsets) {
  std::vector<double> out;
  for (const Onset& o : onsets) out.push_back(o.time_s);
  return out;
}

TEST(OnsetDetection, SilenceAndEmptyBuffersHaveNoOnsets) {
  EXPECT_TRUE(detect_onsets(AudioBuffer{}).empty());
  AudioBuffer silence;
  silence.samples.assign(static_cast<std::size_t>(kRate) * 2, 0);
  EXPECT_TRUE(detect_onsets(silence).empty());
}

TEST(OnsetDetection, InstantAttacksAreFoundWithinAMillisecond) {
  const std::vector<double> starts = {0.25, 0.7513, 1.1, 1.52, 2.0007};
  std::vector<Tone> tones;
  const double pitches[] = {440.0, 220.0, 659.3, 146.8, 523.3};
  for (std::size_t i = 0; i < starts.size(); ++i) {
    tones.push_back({starts[i], starts[i] + 0.3, pitches[i]});
  }
  const auto found = times_of(detect_onsets(mix(tones, 2.6)));
  ASSERT_EQ(found.size(), starts.size());
  for (std::size_t i = 0; i < starts.size(); ++i) {
    EXPECT_NEAR(found[i], starts[i], 0.001) << "tone " << i;
  }
}

TEST(OnsetDetection, RampedAttacksAreFoundAtTheStartOfTheirRise) {
  // A 2..40 ms linear rise: the onset is its start, give or take 2.5 ms.
  for (double attack : {0.002, 0.010, 0.040}) {
    for (double hz : {110.0, 466.0, 932.0}) {
      const auto found = times_of(detect_onsets(mix({{0.5, 1.0, hz, 0.3, attack}}, 1.2)));
      ASSERT_FALSE(found.empty()) << attack << " s attack, " << hz << " Hz";
      EXPECT_NEAR(found[0], 0.5, 0.0025) << attack << " s attack, " << hz << " Hz";
      EXPECT_GE(found[0], 0.5 - 0.0005) << "never before the sound";
    }
  }
}

TEST(OnsetDetection, AHeldToneWithVibratoIsOneOnset) {
  // 6 Hz, ±30 cents: a singer's or a player's vibrato, not new notes.
  const auto found = times_of(detect_onsets(mix({{0.2, 2.2, 392.0, 0.3, 0.01, 6.0, 30.0}}, 2.5)));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0], 0.2, 0.0025);
}

TEST(OnsetDetection, QuietAndLoudNotesInOneFileAreAllFound) {
  const auto found = times_of(detect_onsets(
      mix({{0.3, 0.7, 330.0, 0.5}, {0.9, 1.3, 494.0, 0.05}, {1.5, 1.9, 262.0, 0.5}}, 2.1)));
  ASSERT_EQ(found.size(), 3u);
  EXPECT_NEAR(found[1], 0.9, 0.001);
}

// FluidSynth's own attacks, GM piano (0) and trumpet (56) notes after silence: heard within
// 6 ms after their event frame (the samples' own rise), never before it.
TEST(OnsetDetection, FluidSynthNotesAfterSilenceAreFoundJustAfterTheirEvents) {
  auto font = find_sound_font();
  ASSERT_TRUE(font) << font.error().message;
  for (int program : {0, 56}) {
    music::Score score;
    music::Part part;
    part.program = program;
    score.parts.push_back(part);
    const double onsets[] = {0.5, 1.25, 2.0};
    const int pitches[] = {60, 67, 64};
    for (std::size_t i = 0; i < 3; ++i) {
      music::Note note;
      note.pitch = pitches[i];
      note.onset_s = onsets[i];
      note.offset_s = onsets[i] + 0.4;
      note.velocity = 90;
      score.notes.push_back(note);
    }
    const music::Score* scores[] = {&score};
    auto timeline = build_synth_timeline(scores, {});
    ASSERT_TRUE(timeline) << timeline.error().message;
    auto audio = render_timeline(*timeline, {.sound_font = *font});
    ASSERT_TRUE(audio) << audio.error().message;
    const auto found = times_of(detect_onsets(*audio));
    ASSERT_GE(found.size(), 3u) << "program " << program;
    for (std::size_t i = 0; i < 3; ++i) {
      // The event's frame (block-aligned), not the score time.
      double event_s = 0.0;
      for (const SynthEvent& e : timeline->events) {
        if (e.kind == SynthEventKind::note_on && e.note == static_cast<int>(i)) {
          event_s = static_cast<double>(e.frame) / kRate;
        }
      }
      double nearest = 1e9;
      for (double f : found) {
        if (std::abs(f - event_s) < std::abs(nearest - event_s)) nearest = f;
      }
      EXPECT_GE(nearest - event_s, -0.0005) << "program " << program << " note " << i;
      EXPECT_LE(nearest - event_s, 0.006) << "program " << program << " note " << i;
    }
  }
}

}  // namespace
}  // namespace tutti::audio
