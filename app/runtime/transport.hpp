// SPDX-License-Identifier: MIT
#pragma once
// Transport: play / pause, seek, a loop [A, B) and the practice tempo of a performance, with
// the audio device as the master clock (audio_sync::AudioClock over an audio::LiveOutput).
// Every frame update(host_s) returns the music time to show; the picture follows the sound
// (a slow frame skips time, it never slows the music).
//
//   Transport transport({.start_s = 0, .end_s = 95}, open_audio);  // paused at start_s
//   transport.play(now());
//   every frame: double t = transport.update(now());
//
// Seeking, resuming and a loop's wrap restart the device at the timeline frame of the new time;
// a tempo change opens the sound again through `open_audio` (the events re-timed at the new
// factor). Without `open_audio` the transport is silent and a host-time device stands in.
// The time stays in [start_s, end_s]; at end_s (no loop) it pauses there.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include <tutti/audio/live_output.hpp>
#include <tutti/audio_sync/audio_clock.hpp>
#include <tutti/core/result.hpp>

namespace tutti::runtime {

struct TransportOptions {
  double start_s = 0.0;  // score time of the device's timeline frame 0
  double end_s = 0.0;    // > start_s
  double tempo = 1.0;    // score seconds per audio second, [kMinTempo, kMaxTempo]
  int sample_rate = 48000;
};

// Opens the sound at a tempo factor (timeline frame 0 = TransportOptions::start_s).
using OpenAudio = std::function<Result<std::unique_ptr<audio::LiveOutput>>(double tempo)>;

struct LoopRange {
  double from_s = 0.0;
  double to_s = 0.0;
};

class Transport {
 public:
  // An error for end_s <= start_s, a tempo out of range, or when the sound does not open.
  static Result<std::unique_ptr<Transport>> create(const TransportOptions& options,
                                                   OpenAudio open_audio = {});

  double update(double host_s);

  void play(double host_s);
  void pause(double host_s);
  void toggle(double host_s);
  // Clamped to [start_s, end_s]; playing or paused as before.
  void seek(double host_s, double score_s);

  // [from_s, to_s) clamped to the scene; an error when it is empty.
  Status set_loop(double host_s, double from_s, double to_s);
  // The `[` and `]` keys: one end at a time. The loop acts once both ends are set with A < B.
  void set_loop_start(double host_s, double score_s);
  void set_loop_end(double host_s, double score_s);
  void clear_loop();
  std::optional<LoopRange> loop() const;

  // Reopens the sound at `tempo` and goes on from the same music time.
  Status set_tempo(double host_s, double tempo);
  // Opens the sound again at the same tempo (the music it plays changed: an edit in the editor).
  Status reopen_sound(double host_s);

  bool playing() const { return clock_.playing(); }
  double time() const { return clock_.time(); }
  // The audio clock the frame follows (ScenePlayer::update gives its time to the frame).
  const audio_sync::AudioClock& clock() const { return clock_; }
  double tempo() const { return options_.tempo; }
  double start_s() const { return options_.start_s; }
  double end_s() const { return options_.end_s; }
  // The live device (null when silent).
  const audio::LiveOutput* output() const { return output_.get(); }

 private:
  explicit Transport(const TransportOptions& options);
  audio_sync::DevicePosition device_position(double host_s) const;
  std::int64_t frame_of(double score_s) const;
  void restart_device(double host_s, double score_s);
  void apply_loop();
  Status reopen(double host_s, double tempo);

  TransportOptions options_;
  OpenAudio open_audio_;
  std::unique_ptr<audio::LiveOutput> output_;
  audio_sync::AudioClock clock_;
  double host_device_start_s_ = 0.0;  // silent: the host time of the device's frame 0
  std::optional<double> loop_from_s_;
  std::optional<double> loop_to_s_;
};

}  // namespace tutti::runtime
