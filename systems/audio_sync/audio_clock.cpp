// SPDX-License-Identifier: MIT
#include <tutti/audio_sync/audio_clock.hpp>

#include <algorithm>
#include <cmath>

namespace tutti::audio_sync {

double offline_frame_time(double start_s, int fps, std::int64_t frame, double tempo_factor) {
  return start_s + static_cast<double>(frame) / static_cast<double>(fps) * tempo_factor;
}

AudioClock::AudioClock(const AudioClockOptions& options) : options_(options) {}

void AudioClock::start(double host_s, double score_s) {
  playing_ = true;
  started_ = true;
  origin_score_s_ = score_s;
  host_s_ = host_s;
  shown_s_ = score_s;
  wrapped_ = false;
}

double AudioClock::audio_time(const DevicePosition& device) const {
  const double heard_frames =
      static_cast<double>(std::max<std::int64_t>(0, device.frames_played - device.latency_frames));
  return origin_score_s_ + heard_frames / options_.sample_rate * options_.tempo_factor;
}

double AudioClock::update(double host_s, const DevicePosition& device) {
  if (!playing_ || !std::isfinite(host_s)) {
    if (std::isfinite(host_s)) host_s_ = host_s;
    return shown_s_;
  }
  const double dt = std::max(0.0, host_s - host_s_);
  host_s_ = host_s;
  const double predicted = shown_s_ + dt * rate_ * options_.tempo_factor;
  const double measured = audio_time(device);
  const double error = measured - predicted;
  double next = predicted;
  if (std::abs(error) > options_.resync_s) {
    next = measured;  // a glitch: follow the sound at once (forward only, below)
  } else {
    const double k = options_.correction_per_s;
    next += std::min(1.0, k * dt) * error;
    // Critically damped second-order loop: the rate integrates the error at k^2 / 4.
    rate_ += 0.25 * k * k * error * dt / options_.tempo_factor;
    rate_ = std::clamp(rate_, 0.9, 1.1);
  }
  shown_s_ = std::max(shown_s_, next);
  if (loop_to_s_ > loop_from_s_ && shown_s_ >= loop_to_s_) {
    shown_s_ = loop_from_s_;
    origin_score_s_ = loop_from_s_;  // the caller restarts the audio there, at frame 0
    wrapped_ = true;
  }
  return shown_s_;
}

void AudioClock::pause() { playing_ = false; }

void AudioClock::resume(double host_s) {
  if (!started_) return;
  playing_ = true;
  host_s_ = host_s;
  origin_score_s_ = shown_s_;
}

void AudioClock::seek(double host_s, double score_s) {
  const bool was_playing = playing_;
  start(host_s, score_s);
  playing_ = was_playing;
}

void AudioClock::set_loop(double from_s, double to_s) {
  loop_from_s_ = from_s;
  loop_to_s_ = to_s;
}

bool AudioClock::wrapped() {
  const bool was = wrapped_;
  wrapped_ = false;
  return was;
}

}  // namespace tutti::audio_sync
