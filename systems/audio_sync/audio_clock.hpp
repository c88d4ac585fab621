// SPDX-License-Identifier: MIT
#pragma once
// The engine's clock, taken from the audio (issue 6: "the animation clock locked to the
// synthesized audio").
//
// Offline, frame k of a render shows score time start + k / fps x tempo_factor exactly
// (offline_frame_time). Live, the sound card is the master: AudioClock::update(host_s, device)
// turns the device's report (frames played so far, its output latency) into the score time the
// listener hears now, smoothed between the device's coarse steps (it reports whole periods) so
// the picture never jumps backward, and with the device's rate error (a card 0.1 % fast) learnt
// and followed, so the picture stays on the sound for as long as it plays. seek / pause / resume
// / loop act on the clock and say where the audio must go.
//
//   AudioClock clock({.sample_rate = 48000, .tempo_factor = 1.0});
//   clock.start(host_now, 0.0);
//   every frame: double t = clock.update(host_now, device.position());

#include <cstdint>

namespace tutti::audio_sync {

// Score time of offline frame k.
double offline_frame_time(double start_s, int fps, std::int64_t frame, double tempo_factor = 1.0);

// What an audio device says about itself at one moment.
struct DevicePosition {
  std::int64_t frames_played = 0;   // handed to the hardware since start() (monotonic)
  std::int64_t latency_frames = 0;  // still between the hardware and the listener's ears
};

struct AudioClockOptions {
  int sample_rate = 48000;
  double tempo_factor = 1.0;  // score seconds per audio second
  // How fast the picture is pulled onto the sound (1/s). The device's rate is learnt at the
  // critically damped rate for it (a second-order loop: no lasting error under a steady drift).
  double correction_per_s = 2.0;
  // Errors beyond this (seconds) are not smoothed: the clock jumps (a glitch or an xrun).
  double resync_s = 0.25;
};

class AudioClock {
 public:
  explicit AudioClock(const AudioClockOptions& options = {});

  // Starts (or restarts) playing from score time `score_s` at host time `host_s`; the device's
  // frame count restarts at 0 with it.
  void start(double host_s, double score_s);
  // The score time to show at host_s. Never less than the previous result while playing (except
  // across seek or a loop's wrap). Before start() or while paused: the held time.
  double update(double host_s, const DevicePosition& device);

  // Pausing holds the time; resume() continues from it (the device restarts at frame 0).
  void pause();
  void resume(double host_s);
  // Jumps to score_s (the device restarts at frame 0 from there).
  void seek(double host_s, double score_s);
  // Plays [from_s, to_s) over and over: when the time reaches to_s, it wraps to from_s and
  // wrapped() says so once (the caller restarts the audio there). to_s <= from_s: no loop.
  void set_loop(double from_s, double to_s);
  bool wrapped();

  bool playing() const { return playing_; }
  double time() const { return shown_s_; }
  // The learnt device rate relative to nominal (1.001 = 0.1 % fast).
  double device_rate() const { return rate_; }

 private:
  double audio_time(const DevicePosition& device) const;

  AudioClockOptions options_;
  bool playing_ = false;
  double origin_score_s_ = 0.0;  // score time at device frame 0
  double host_s_ = 0.0;          // last update
  double shown_s_ = 0.0;         // last result
  double rate_ = 1.0;            // device seconds per host second, learnt
  double loop_from_s_ = 0.0;
  double loop_to_s_ = 0.0;
  bool wrapped_ = false;
  bool started_ = false;
};

}  // namespace tutti::audio_sync
