// SPDX-License-Identifier: MIT
#pragma once
// A LiveNoteSource that replays a list of events at their times: tests and benchmarks feed the
// live path exactly as a MIDI device would, without hardware.

#include <cstddef>
#include <vector>

#include <tutti/live/live_note_event.hpp>

namespace tutti::live {

class ScriptedSource final : public LiveNoteSource {
 public:
  // Events are sorted by time (stable), so the script may list them in any order.
  explicit ScriptedSource(std::vector<LiveNoteEvent> events);
  void poll(double now_s, std::vector<LiveNoteEvent>& out) override;
  std::string name() const override { return "script"; }
  bool done() const { return next_ == events_.size(); }

 private:
  std::vector<LiveNoteEvent> events_;
  std::size_t next_ = 0;
};

}  // namespace tutti::live
