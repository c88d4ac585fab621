// SPDX-License-Identifier: MIT
// The audio clock (audio_sync/audio_clock.hpp) against a simulated device: it never goes
// backward, stays within a frame of what is heard for 10 simulated minutes with a device 0.1 %
// fast (and slow), learns the device's rate, and seeks, pauses and loops.
#include <tutti/audio_sync/audio_clock.hpp>

#include <gtest/gtest.h>

#include <cmath>

#include <tutti/audio_sync/simulated_device.hpp>

namespace tutti::audio_sync {
namespace {

constexpr double kFrame = 1.0 / 60.0;

struct ClockRun {
  double worst_error_s = 0.0;  // after the first second
  bool monotonic = true;
  double learnt_rate = 1.0;
};

// 60 fps updates for `minutes` of host time, host clock jittered by up to 2 ms a frame.
ClockRun run(double device_rate, double minutes, double tempo = 1.0) {
  SimulatedDeviceOptions device_options;
  device_options.rate = device_rate;
  SimulatedDevice device(device_options);
  AudioClockOptions options;
  options.tempo_factor = tempo;
  AudioClock clock(options);
  const double host0 = 1000.0;
  device.start(host0);
  clock.start(host0, 5.0);
  ClockRun r;
  double previous = clock.time();
  const auto frames = static_cast<int>(minutes * 60.0 * 60.0);
  for (int k = 1; k <= frames; ++k) {
    const double jitter = 0.002 * std::sin(k * 12.9898);
    const double host = host0 + k * kFrame + jitter;
    const double t = clock.update(host, device.position(host));
    if (t < previous) r.monotonic = false;
    previous = t;
    const double heard = 5.0 + device.heard_s(host) * tempo;
    if (k * kFrame > 1.0) r.worst_error_s = std::max(r.worst_error_s, std::abs(t - heard));
  }
  r.learnt_rate = clock.device_rate();
  return r;
}

TEST(AudioClock, OfflineFrameTimesAreExact) {
  EXPECT_EQ(offline_frame_time(0.0, 30, 0), 0.0);
  EXPECT_EQ(offline_frame_time(-2.5, 30, 75), 0.0);
  EXPECT_DOUBLE_EQ(offline_frame_time(1.0, 60, 90), 2.5);
  EXPECT_DOUBLE_EQ(offline_frame_time(0.0, 30, 60, 0.5), 1.0);  // half tempo: 2 s show 1 s
}

TEST(AudioClock, ADeviceATenthOfAPercentFastStaysWithinAFrameForTenMinutes) {
  const ClockRun fast = run(1.001, 10.0);
  EXPECT_TRUE(fast.monotonic);
  EXPECT_LT(fast.worst_error_s, kFrame) << fast.worst_error_s;
  EXPECT_NEAR(fast.learnt_rate, 1.001, 3e-4);
  const ClockRun slow = run(0.999, 10.0);
  EXPECT_TRUE(slow.monotonic);
  EXPECT_LT(slow.worst_error_s, kFrame) << slow.worst_error_s;
  EXPECT_NEAR(slow.learnt_rate, 0.999, 3e-4);
  std::printf("clock error over 10 min at 60 fps: 0.1 %% fast %.2f ms, 0.1 %% slow %.2f ms\n",
              1000.0 * fast.worst_error_s, 1000.0 * slow.worst_error_s);
}

TEST(AudioClock, AtHalfTempoTheClockStillFollowsTheSound) {
  const ClockRun half_tempo = run(1.001, 2.0, 0.5);
  EXPECT_TRUE(half_tempo.monotonic);
  EXPECT_LT(half_tempo.worst_error_s, kFrame) << half_tempo.worst_error_s;
}

TEST(AudioClock, AGlitchForwardIsFollowedAtOnceAndNeverBackward) {
  AudioClock clock;
  clock.start(0.0, 0.0);
  double t = 0.0;
  for (int k = 1; k <= 60; ++k) t = clock.update(k * kFrame, {k * 800, 0});
  EXPECT_NEAR(t, 1.0, 0.01);
  // The device skips half a second (an underrun recovered by dropping audio).
  t = clock.update(61 * kFrame, {61 * 800 + 24000, 0});
  EXPECT_NEAR(t, 61 * kFrame + 0.5, 0.001);
  // ... and then reports a position 0.3 s behind: the picture waits rather than rewinding.
  const double before = t;
  t = clock.update(62 * kFrame, {62 * 800, 0});
  EXPECT_GE(t, before);
}

TEST(AudioClock, SeekPauseResumeAndLoop) {
  SimulatedDevice device;
  AudioClock clock;
  EXPECT_EQ(clock.update(0.0, {}), 0.0);  // not started: held
  device.start(0.0);
  clock.start(0.0, 0.0);
  double t = 0.0;
  for (int k = 1; k <= 120; ++k) t = clock.update(k * kFrame, device.position(k * kFrame));
  EXPECT_NEAR(t, 2.0 - 1024.0 / 48000.0, kFrame);
  clock.seek(2.0, 20.0);
  device.start(2.0);
  EXPECT_EQ(clock.time(), 20.0);
  for (int k = 1; k <= 60; ++k)
    t = clock.update(2.0 + k * kFrame, device.position(2.0 + k * kFrame));
  EXPECT_GT(t, 20.9);
  EXPECT_LT(t, 21.0);
  clock.pause();
  const double held = clock.time();
  EXPECT_EQ(clock.update(10.0, device.position(10.0)), held);
  EXPECT_FALSE(clock.playing());
  clock.resume(10.0);
  device.start(10.0);
  clock.set_loop(20.0, 21.5);
  bool wrapped = false;
  double previous = held;
  for (int k = 1; k <= 120; ++k) {
    const double host = 10.0 + k * kFrame;
    t = clock.update(host, device.position(host));
    if (clock.wrapped()) {
      wrapped = true;
      EXPECT_EQ(t, 20.0);
      device.start(host);
    } else {
      EXPECT_GE(t, previous);
    }
    previous = t;
    EXPECT_LT(t, 21.5);
  }
  EXPECT_TRUE(wrapped);
}

}  // namespace
}  // namespace tutti::audio_sync
