// SPDX-License-Identifier: MIT
#include <tutti/music/score.hpp>

#include <algorithm>
#include <tuple>

namespace tutti::music {

void finalize_score(Score& score) {
  const TempoMap& map = score.tempo_map;
  auto seconds = [&](std::int64_t tick) { return map.seconds_at(static_cast<double>(tick)); };
  auto beats = [&](std::int64_t tick) { return map.beats_at(static_cast<double>(tick)); };

  std::stable_sort(score.notes.begin(), score.notes.end(), [](const Note& a, const Note& b) {
    return std::tie(a.onset_ticks, a.pitch, a.part) < std::tie(b.onset_ticks, b.pitch, b.part);
  });
  for (Note& note : score.notes) {
    note.offset_ticks = std::max(note.offset_ticks, note.onset_ticks);
    note.onset_s = seconds(note.onset_ticks);
    note.offset_s = seconds(note.offset_ticks);
    note.onset_beats = beats(note.onset_ticks);
    note.offset_beats = beats(note.offset_ticks);
    score.end_ticks = std::max(score.end_ticks, note.offset_ticks);
  }

  auto by_tick = [](const auto& a, const auto& b) { return a.tick < b.tick; };
  std::stable_sort(score.time_signatures.begin(), score.time_signatures.end(), by_tick);
  std::stable_sort(score.key_signatures.begin(), score.key_signatures.end(), by_tick);
  std::stable_sort(score.texts.begin(), score.texts.end(), by_tick);
  for (auto& ts : score.time_signatures) ts.seconds = seconds(ts.tick);
  for (auto& ks : score.key_signatures) ks.seconds = seconds(ks.tick);
  for (auto& text : score.texts) text.seconds = seconds(text.tick);

  std::stable_sort(score.pedal_spans.begin(), score.pedal_spans.end(),
                   [](const PedalSpan& a, const PedalSpan& b) {
                     return std::tie(a.part, a.onset_ticks) < std::tie(b.part, b.onset_ticks);
                   });
  for (auto& pedal : score.pedal_spans) {
    pedal.offset_ticks = std::max(pedal.offset_ticks, pedal.onset_ticks);
    pedal.onset_s = seconds(pedal.onset_ticks);
    pedal.offset_s = seconds(pedal.offset_ticks);
    score.end_ticks = std::max(score.end_ticks, pedal.offset_ticks);
  }
  score.end_s = seconds(score.end_ticks);
}

}  // namespace tutti::music
