// SPDX-License-Identifier: MIT
#pragma once
// Live MIDI from the ALSA sequencer: opens a client "tutti" with one input port "live in" and,
// when asked, subscribes it to a source port. `port`:
//   ""        no connection (connect it yourself: `aconnect <keyboard> tutti`)
//   "auto"    every readable port of the other clients except the system's and "Midi Through"
//   "20:0"    client:port numbers, or a client's name ("USB Keystation:0", "Keystation")
// Note-ons (velocity 0 = note-off) and note-offs are stamped with the poll's time: an event
// waits at most one poll (one frame) in the sequencer's queue before it is seen.
//
// Errors (one line, no crash): no sequencer (/dev/snd/seq missing: "ALSA sequencer: cannot
// open (No such file or directory)"), an unknown port name, a port that refuses the connection.

#include <memory>
#include <string>

#include <tutti/core/result.hpp>
#include <tutti/live/live_note_event.hpp>

namespace tutti::live {

class AlsaMidiSource final : public LiveNoteSource {
 public:
  static Result<std::unique_ptr<AlsaMidiSource>> open(const std::string& port);
  ~AlsaMidiSource() override;
  AlsaMidiSource(const AlsaMidiSource&) = delete;
  AlsaMidiSource& operator=(const AlsaMidiSource&) = delete;

  void poll(double now_s, std::vector<LiveNoteEvent>& out) override;
  std::string name() const override { return name_; }
  int connections() const { return connections_; }

 private:
  AlsaMidiSource() = default;
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string name_;
  int connections_ = 0;
};

// The sequencer device's path ("/dev/snd/seq"), for messages.
const char* alsa_sequencer_device();

}  // namespace tutti::live
