// SPDX-License-Identifier: MIT
#pragma once
// An audio device that is not there: it "plays" in whole periods at its own rate (a crystal a
// little fast or slow) and reports the position and latency a real one would. tutti play uses it
// when no sound card exists, so the clock behaves the same with and without one; tests use it to
// measure the clock.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <tutti/audio_sync/audio_clock.hpp>

namespace tutti::audio_sync {

struct SimulatedDeviceOptions {
  int sample_rate = 48000;
  int period_frames = 512;    // the position advances in these steps
  int latency_frames = 1024;  // two periods queued
  double rate = 1.0;          // 1.001 = 0.1 % fast
};

class SimulatedDevice {
 public:
  explicit SimulatedDevice(const SimulatedDeviceOptions& options = {}) : options_(options) {}
  // The device starts playing at host_s (frame 0).
  void start(double host_s) { start_s_ = host_s; }
  DevicePosition position(double host_s) const {
    const double frames = std::max(0.0, host_s - start_s_) * options_.sample_rate * options_.rate;
    const auto periods = static_cast<std::int64_t>(std::floor(frames / options_.period_frames));
    return {periods * options_.period_frames, options_.latency_frames};
  }
  // What the listener hears at host_s, in seconds of audio since start (continuous).
  double heard_s(double host_s) const {
    return std::max(0.0, (host_s - start_s_) * options_.rate -
                             static_cast<double>(options_.latency_frames) / options_.sample_rate);
  }

 private:
  SimulatedDeviceOptions options_;
  double start_s_ = 0.0;
};

}  // namespace tutti::audio_sync
