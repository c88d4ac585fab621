// SPDX-License-Identifier: MIT
#pragma once
// Live note input: what a MIDI keyboard (ALSA sequencer), the computer keyboard or a test script
// sends, and the one interface `tutti play` polls every frame. Sources are polled from one
// thread (the frame loop); none blocks.

#include <string>
#include <vector>

namespace tutti::live {

struct LiveNoteEvent {
  double time_s = 0.0;  // host seconds on the poller's clock (the `now_s` of poll())
  int key = 60;         // MIDI key 0..127
  int velocity = 100;   // 1..127 for a note-on; ignored for a note-off
  bool on = true;       // false: the key was released
};

class LiveNoteSource {
 public:
  virtual ~LiveNoteSource() = default;
  // Appends every event that has arrived up to now_s, in time order (times <= now_s).
  virtual void poll(double now_s, std::vector<LiveNoteEvent>& out) = 0;
  // For messages: "ALSA 128:0 (tutti)", "computer keyboard", "script".
  virtual std::string name() const = 0;
};

}  // namespace tutti::live
