// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/tie_merge.hpp>

#include <algorithm>
#include <climits>
#include <map>
#include <utility>

namespace tutti::music::musicxml {

std::vector<Note> merge_ties(std::vector<TieMarkedNote> notes) {
  std::stable_sort(notes.begin(), notes.end(), [](const TieMarkedNote& a, const TieMarkedNote& b) {
    return a.note.onset_ticks < b.note.onset_ticks;
  });
  std::vector<Note> merged;
  merged.reserve(notes.size());
  // (pitch, voice) -> index in `merged` of the note whose tie is still open.
  std::map<std::pair<int, int>, std::size_t> open;

  auto find_open = [&](const Note& note) {
    auto same_voice = open.find({note.pitch, note.voice});
    if (same_voice != open.end()) return same_voice;
    auto any_voice = open.lower_bound({note.pitch, INT_MIN});
    return any_voice != open.end() && any_voice->first.first == note.pitch ? any_voice : open.end();
  };

  for (TieMarkedNote& marked : notes) {
    Note& note = marked.note;
    if (note.grace) {
      merged.push_back(note);
      continue;
    }
    if (marked.tie_stop) {
      auto it = find_open(note);
      if (it != open.end() && merged[it->second].onset_ticks <= note.onset_ticks) {
        Note& first = merged[it->second];
        first.offset_ticks = std::max(first.offset_ticks, note.offset_ticks);
        if (!marked.tie_start) open.erase(it);
        continue;
      }
    }
    open.erase({note.pitch, note.voice});
    merged.push_back(note);
    if (marked.tie_start) open[{note.pitch, note.voice}] = merged.size() - 1;
  }
  return merged;
}

}  // namespace tutti::music::musicxml
