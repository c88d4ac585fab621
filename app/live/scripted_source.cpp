// SPDX-License-Identifier: MIT
#include <tutti/live/scripted_source.hpp>

#include <algorithm>

namespace tutti::live {

ScriptedSource::ScriptedSource(std::vector<LiveNoteEvent> events) : events_(std::move(events)) {
  std::stable_sort(
      events_.begin(), events_.end(),
      [](const LiveNoteEvent& a, const LiveNoteEvent& b) { return a.time_s < b.time_s; });
}

void ScriptedSource::poll(double now_s, std::vector<LiveNoteEvent>& out) {
  while (next_ < events_.size() && events_[next_].time_s <= now_s) out.push_back(events_[next_++]);
}

}  // namespace tutti::live
