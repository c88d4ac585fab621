// SPDX-License-Identifier: MIT
// Live output (audio/live_output.hpp): the simulated device's position, the audio pulled as the
// driver would pull it equal to the offline render, seeking, an AudioClock following it, and a
// real device when this machine has one (else the clear error without the simulated fallback).
#include <tutti/audio/live_output.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include <tutti/audio/offline_synth.hpp>
#include <tutti/audio/sound_font.hpp>
#include <tutti/audio_sync/audio_clock.hpp>

namespace tutti::audio {
namespace {

SynthTimeline two_notes() {
  music::Score score;
  score.parts.push_back(music::Part{});
  for (auto [pitch, onset] : {std::pair{60, 0.25}, {67, 0.75}}) {
    music::Note note;
    note.pitch = pitch;
    note.onset_s = onset;
    note.offset_s = onset + 0.4;
    note.velocity = 90;
    score.notes.push_back(note);
  }
  const music::Score* scores[] = {&score};
  auto timeline = build_synth_timeline(scores, {});
  EXPECT_TRUE(timeline);
  return *timeline;
}

class LiveOutputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto font = find_sound_font();
    ASSERT_TRUE(font) << font.error().message;
    font_ = *font;
  }
  std::unique_ptr<LiveOutput> open_simulated(const SynthTimeline& timeline) {
    auto out = LiveOutput::open(timeline, {.sound_font = font_, .driver = "simulated"});
    EXPECT_TRUE(out) << out.error().message;
    return out ? std::move(*out) : nullptr;
  }
  std::filesystem::path font_;
};

std::int16_t pcm(float v) {
  return static_cast<std::int16_t>(std::nearbyint(std::clamp(v, -1.0f, 1.0f) * 32767.0f));
}

TEST_F(LiveOutputTest, ASimulatedDeviceReportsWholePeriodsFromTheHostClock) {
  auto out = open_simulated(two_notes());
  ASSERT_TRUE(out);
  EXPECT_TRUE(out->simulated());
  EXPECT_EQ(out->device(), "simulated");
  EXPECT_EQ(out->position(5.0).frames_played, 0);
  out->play(10.0, 0);
  EXPECT_EQ(out->position(10.0).frames_played, 0);
  EXPECT_EQ(out->position(10.5).frames_played, 24000 / 512 * 512);
  EXPECT_EQ(out->position(10.5).latency_frames, 1024);
  out->stop(11.0);
  EXPECT_EQ(out->position(20.0).frames_played, 48000 / 512 * 512) << "held while stopped";
  out->play(30.0, 48000);
  EXPECT_EQ(out->position(30.1).frames_played, 4800 / 512 * 512) << "restarts at 0";
}

TEST_F(LiveOutputTest, PulledAudioIsTheOfflineRender) {
  const SynthTimeline timeline = two_notes();
  auto out = open_simulated(timeline);
  ASSERT_TRUE(out);
  out->play(0.0, 0);
  constexpr int kFrames = 72000;
  std::vector<float> left(kFrames), right(kFrames);
  // Uneven pulls, as a driver's periods need not be blocks.
  for (int at = 0; at < kFrames;) {
    const int n = std::min(300 + (at / 300) % 7 * 37, kFrames - at);
    out->render(n, left.data() + at, right.data() + at);
    at += n;
  }
  auto offline = render_timeline(timeline, {.sound_font = font_, .frames = kFrames});
  ASSERT_TRUE(offline) << offline.error().message;
  int differing = 0, loud = 0;
  for (int i = 0; i < kFrames; ++i) {
    differing += std::abs(pcm(left[i]) - offline->samples[2 * i]) > 1;
    differing += std::abs(pcm(right[i]) - offline->samples[2 * i + 1]) > 1;
    loud += std::abs(offline->samples[2 * i]) > 1000;
  }
  EXPECT_GT(loud, 1000) << "the notes sound";
  EXPECT_EQ(differing, 0);
}

TEST_F(LiveOutputTest, PlayingFromAFrameStartsThereInSilence) {
  auto out = open_simulated(two_notes());
  ASSERT_TRUE(out);
  out->play(0.0, 24000);  // 0.5 s: between the two notes' onsets (0.25 s and 0.75 s)
  std::vector<float> left(24000), right(24000);
  out->render(24000, left.data(), right.data());
  float before = 0.0f, after = 0.0f;
  for (int i = 0; i < 24000; ++i) {
    (i < 11900 ? before : after) = std::max(i < 11900 ? before : after, std::abs(left[i]));
  }
  EXPECT_LT(before, 1e-4f) << "the first note was cut by the seek (-80 dB)";
  EXPECT_GT(after, 0.02f) << "the second note sounds from 0.75 s";
  // Stopped: silence, and the position does not move.
  out->stop(1.0);
  out->render(512, left.data(), right.data());
  EXPECT_EQ(*std::max_element(left.begin(), left.begin() + 512), 0.0f);
}

TEST_F(LiveOutputTest, AnAudioClockFollowsTheSimulatedDevice) {
  auto out = open_simulated(two_notes());
  ASSERT_TRUE(out);
  audio_sync::AudioClock clock({.sample_rate = 48000});
  out->play(100.0, 0);
  clock.start(100.0, 0.0);
  double worst = 0.0;
  for (int k = 0; k < 600; ++k) {  // 10 s at 60 fps
    const double host = 100.0 + k / 60.0;
    const LivePosition p = out->position(host);
    const double t = clock.update(host, {p.frames_played, p.latency_frames});
    const double heard = std::max(0.0, host - 100.0 - 1024.0 / 48000.0);
    if (k > 60) worst = std::max(worst, std::abs(t - heard));
  }
  EXPECT_LT(worst, 1.0 / 60.0);
}

// This machine's sound card if it has one: it takes audio and its position moves. Without one
// (CI), the fallback is the simulated device, and refusing the fallback is a one-line error
// naming the driver.
TEST_F(LiveOutputTest, ARealDeviceOrAClearError) {
  const SynthTimeline timeline = two_notes();
  LiveOutputOptions options;
  options.sound_font = font_;
  auto out = LiveOutput::open(timeline, options);
  ASSERT_TRUE(out) << out.error().message;
  if ((*out)->simulated()) {
    options.allow_simulated = false;
    auto strict = LiveOutput::open(timeline, options);
    ASSERT_FALSE(strict);
    EXPECT_NE(strict.error().message.find("driver"), std::string::npos) << strict.error().message;
    EXPECT_EQ(strict.error().message.find('\n'), std::string::npos);
    std::printf("no audio device here: %s\n", strict.error().message.c_str());
    return;
  }
  std::printf("audio device: %s\n", (*out)->device().c_str());
  const auto start = std::chrono::steady_clock::now();
  (*out)->play(0.0, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::int64_t played = (*out)->position(elapsed).frames_played;
  EXPECT_GT(played, 0);
  EXPECT_LT(played, static_cast<std::int64_t>((elapsed + 0.2) * 48000));
}

TEST_F(LiveOutputTest, AMissingSoundFontIsAnError) {
  auto out =
      LiveOutput::open(two_notes(), {.sound_font = "/nonexistent.sf2", .driver = "simulated"});
  ASSERT_FALSE(out);
  EXPECT_NE(out.error().message.find("/nonexistent.sf2"), std::string::npos);
}

}  // namespace
}  // namespace tutti::audio
