// SPDX-License-Identifier: MIT
#pragma once
// A SynthTimeline played in real time through FluidSynth's audio driver (PulseAudio, ALSA, …,
// whichever FluidSynth finds, or the one named), reporting what a clock needs: how many frames
// it has handed to the device and how many are still queued before the listener hears them
// (audio_sync::AudioClock turns that into the time to show). With no device, a simulated one
// keeps the same promises from the host clock, silently — a game without a sound card still
// gets a clock that behaves like a device.
//
//   auto out = LiveOutput::open(timeline, {.sound_font = font});
//   out->play(host_now, 0);
//   every frame: auto p = out->position(host_now);  // -> AudioClock::update
//
// The driver's thread calls render(); tests call it directly to pull the audio without a
// device. Events are applied on FluidSynth's 64-frame blocks as offline (synth_events.hpp), so
// live and offline give the same notes at the same frames.

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include <tutti/audio/synth_events.hpp>
#include <tutti/core/result.hpp>

namespace tutti::audio {

struct LiveOutputOptions {
  std::filesystem::path sound_font;
  std::string driver;       // a FluidSynth audio driver; empty: its default; "simulated": none
  int period_frames = 512;  // the device takes audio in these steps
  int periods = 2;          // this many queued: the output latency
  double gain = 0.5;
  bool allow_simulated = true;  // no device: simulate one (else an error)
};

struct LivePosition {
  std::int64_t frames_played = 0;   // handed to the device since play() (monotonic)
  std::int64_t latency_frames = 0;  // queued between the device and the listener
};

class LiveOutput {
 public:
  // Errors: the sound font does not load, FluidSynth cannot start, or no device and
  // !allow_simulated (the message names the driver).
  static Result<std::unique_ptr<LiveOutput>> open(const SynthTimeline& timeline,
                                                  const LiveOutputOptions& options);
  ~LiveOutput();
  LiveOutput(const LiveOutput&) = delete;
  LiveOutput& operator=(const LiveOutput&) = delete;

  bool simulated() const { return simulated_; }
  const std::string& device() const { return device_; }  // the driver's name, or "simulated"
  int sample_rate() const { return timeline_.sample_rate; }

  // Plays from timeline frame `frame` (down to its 64-frame block) from host time host_s on;
  // frames_played restarts at 0. Also a seek.
  void play(double host_s, std::int64_t frame);
  // Silence from the next period on; the position holds.
  void stop(double host_s);
  LivePosition position(double host_s) const;

  // Fills `frames` frames of left/right (the driver's callback): the timeline from where it
  // is, or silence when stopped. Only ever on one thread at a time.
  void render(int frames, float* left, float* right);

 private:
  LiveOutput() = default;
  void apply_seek(std::int64_t frame);

  SynthTimeline timeline_;
  LiveOutputOptions options_;
  struct Impl;
  std::unique_ptr<Impl> impl_;
  bool simulated_ = false;
  std::string device_;

  std::atomic<std::int64_t> handed_{0};  // frames rendered while playing, ever
  std::atomic<std::int64_t> handed_at_play_{0};
  std::atomic<std::int64_t> seek_to_{-1};  // pending, for the render thread
  std::atomic<bool> playing_{false};
  // Simulated device: the host time of play() and the frames held at stop().
  std::atomic<double> started_host_s_{0.0};
  std::atomic<std::int64_t> held_frames_{0};
  // Render thread only.
  std::int64_t at_ = 0;   // timeline frame
  std::size_t next_ = 0;  // next event
};

}  // namespace tutti::audio
