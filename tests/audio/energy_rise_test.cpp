// SPDX-License-Identifier: MIT
// Where a sound starts by its energy (audio/energy_rise.hpp): a tone out of silence, a tone
// entering over a sustained bass note (whose ripple is not a rise), and a span with no rise.
#include <tutti/audio/energy_rise.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tutti::audio {
namespace {

constexpr int kSampleRate = 48000;

// Stereo 16-bit: a `bass_hz` tone throughout (amplitude `bass`), plus a `tone_hz` tone from
// `start_s` (amplitude `tone`, a 1 ms linear fade-in).
AudioBuffer tones(double seconds, double bass_hz, double bass, double tone_hz, double tone,
                  double start_s) {
  AudioBuffer audio;
  audio.sample_rate = kSampleRate;
  audio.channels = 2;
  const auto frames = static_cast<std::size_t>(seconds * kSampleRate);
  for (std::size_t f = 0; f < frames; ++f) {
    const double t = static_cast<double>(f) / kSampleRate;
    double x = bass * std::sin(2 * std::numbers::pi * bass_hz * t);
    if (t >= start_s) {
      x += tone * std::min(1.0, (t - start_s) / 0.001) *
           std::sin(2 * std::numbers::pi * tone_hz * (t - start_s));
    }
    const auto sample = static_cast<std::int16_t>(std::lround(x * 32767.0));
    audio.samples.push_back(sample);
    audio.samples.push_back(sample);
  }
  return audio;
}

TEST(EnergyRise, AToneOutOfSilenceStartsWhereItEntersTheWindow) {
  const AudioBuffer audio = tones(0.5, 0.0, 0.0, 440.0, 0.5, 0.2);
  EXPECT_NEAR(steepest_energy_rise_s(audio, 0.15, 0.25, -1.0), 0.2, 0.0015);
}

TEST(EnergyRise, AToneOverASustainedBassNoteIsFoundNotTheRipple) {
  // 55 Hz at -10 dBFS throughout; a 660 Hz tone at -6 dBFS joins at 0.3 s.
  const AudioBuffer audio = tones(0.6, 55.0, 0.3, 660.0, 0.5, 0.3);
  EXPECT_NEAR(steepest_energy_rise_s(audio, 0.28, 0.32, -1.0), 0.3, 0.003);
}

TEST(EnergyRise, NoRiseGivesTheFallbackAndBadSpansAreSafe) {
  const AudioBuffer silence = tones(0.2, 0.0, 0.0, 440.0, 0.0, 0.0);
  EXPECT_EQ(steepest_energy_rise_s(silence, 0.05, 0.15, 0.123), 0.123);
  const AudioBuffer audio = tones(0.2, 0.0, 0.0, 440.0, 0.5, 0.1);
  EXPECT_EQ(steepest_energy_rise_s(audio, 0.15, 0.05, 0.5), 0.5);    // empty span
  EXPECT_EQ(steepest_energy_rise_s(audio, 5.0, 6.0, 0.5), 0.5);      // beyond the end
  EXPECT_EQ(steepest_energy_rise_s(AudioBuffer{}, 0.0, 1.0, 0.5), 0.5);
}

}  // namespace
}  // namespace tutti::audio
