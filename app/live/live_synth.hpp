// SPDX-License-Identifier: MIT
#pragma once
// Live notes made audible: a FluidSynth synth (General MIDI piano, channel 1) on the sound
// card through FluidSynth's audio driver, note-ons and note-offs sent the moment they are
// polled. The output latency is the driver's (period × periods, about 21 ms at 48 kHz with
// 512 × 2). Without a sound card open() fails (the caller plays on silently).

#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include <tutti/core/result.hpp>
#include <tutti/live/live_note_event.hpp>

namespace tutti::live {

class LiveSynth {
 public:
  // Errors: the sound font does not load, FluidSynth cannot start, no audio device.
  static Result<std::unique_ptr<LiveSynth>> open(const std::filesystem::path& sound_font,
                                                 const std::string& driver = "");
  ~LiveSynth();
  LiveSynth(const LiveSynth&) = delete;
  LiveSynth& operator=(const LiveSynth&) = delete;

  void play(std::span<const LiveNoteEvent> events);
  const std::string& device() const { return device_; }

 private:
  LiveSynth() = default;
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string device_;
};

}  // namespace tutti::live
