// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/brass_lines.hpp>

#include <algorithm>
#include <string>

namespace tutti::fingering_planner {

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::detect_instrument;
using brass_model::Instrument;
using brass_model::LineNote;

namespace {

// Distinct stated voice numbers of a part, ascending (empty or one = not split by voice).
std::vector<int> stated_voices(const music::Score& score, int part) {
  std::vector<int> voices;
  for (const music::Note& n : score.notes) {
    if (n.part != part || n.voice <= 0) continue;
    if (std::find(voices.begin(), voices.end(), n.voice) == voices.end()) voices.push_back(n.voice);
  }
  std::sort(voices.begin(), voices.end());
  return voices;
}

// Most notes of the part (or of one stated voice) starting together.
int most_at_once(const music::Score& score, int part, int voice) {
  int most = 0;
  std::int64_t tick = -1;
  int count = 0;
  for (const music::Note& n : score.notes) {  // sorted by onset
    if (n.part != part || (voice > 0 && n.voice != voice) || n.grace) continue;
    count = n.onset_ticks == tick ? count + 1 : 1;
    tick = n.onset_ticks;
    most = std::max(most, count);
  }
  return most;
}

}  // namespace

int voices_in_part(const music::Score& score, int part) {
  const std::vector<int> stated = stated_voices(score, part);
  if (stated.size() > 1) return static_cast<int>(stated.size());
  return std::max(1, most_at_once(score, part, 0));
}

std::vector<BrassPart> find_brass_parts(const music::Score& score,
                                        std::span<const Instrument> known) {
  std::vector<BrassPart> parts;
  for (std::size_t p = 0; p < score.parts.size(); ++p) {
    const Instrument* instrument = detect_instrument(score.parts[p], known);
    if (instrument == nullptr) continue;
    const int part = static_cast<int>(p);
    bool has_notes = false;
    for (const music::Note& n : score.notes) has_notes = has_notes || n.part == part;
    if (has_notes) parts.push_back({part, instrument, voices_in_part(score, part)});
  }
  return parts;
}

Result<BrassLine> extract_line(const music::Score& score, int part, int voice,
                               const Instrument& instrument) {
  if (part < 0 || static_cast<std::size_t>(part) >= score.parts.size()) {
    return Error{score.source + ": no part " + std::to_string(part + 1) + " (the score has " +
                 std::to_string(score.parts.size()) + ")"};
  }
  const int voices = voices_in_part(score, part);
  if (voice < 0 || voice >= voices) {
    return Error{score.source + ": part " + std::to_string(part + 1) + " has " +
                 std::to_string(voices) + " voice(s), not " + std::to_string(voice + 1)};
  }
  BrassLine line;
  line.part = part;
  line.voice = voice;
  line.part_name = score.parts[static_cast<std::size_t>(part)].name;
  line.instrument = &instrument;

  const std::vector<int> stated = stated_voices(score, part);
  const int only_voice = stated.size() > 1 ? stated[static_cast<std::size_t>(voice)] : 0;
  const int rank = stated.size() > 1 ? 0 : voice;  // chord member to take, from the top
  std::vector<int> chord;                          // Score::notes indices starting together
  auto take = [&] {
    if (chord.empty()) return;
    std::sort(chord.begin(), chord.end(), [&](int a, int b) {
      return score.notes[static_cast<std::size_t>(a)].pitch >
             score.notes[static_cast<std::size_t>(b)].pitch;
    });
    const int index = chord[static_cast<std::size_t>(std::min<int>(rank, int(chord.size()) - 1))];
    const music::Note& n = score.notes[static_cast<std::size_t>(index)];
    LineNote note;
    note.score_index = index;
    note.onset_s = n.onset_s;
    note.offset_s = std::max(n.offset_s, n.onset_s);
    note.onset_beats = n.onset_beats;
    note.offset_beats = std::max(n.offset_beats, n.onset_beats);
    note.sounding = n.pitch;
    note.written = instrument.written(n.pitch);
    note.velocity = n.velocity;
    note.playable = instrument.in_range_written(note.written);
    line.notes.push_back(note);
    chord.clear();
  };
  std::int64_t tick = -1;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    const music::Note& n = score.notes[i];
    if (n.part != part || (only_voice > 0 && n.voice != only_voice)) continue;
    if (n.onset_ticks != tick) take();
    tick = n.onset_ticks;
    chord.push_back(static_cast<int>(i));
  }
  take();
  // Monophonic: a note ends when the next one starts.
  for (std::size_t k = 0; k + 1 < line.notes.size(); ++k) {
    LineNote& note = line.notes[k];
    const LineNote& next = line.notes[k + 1];
    if (note.offset_s > next.onset_s) {
      note.offset_s = next.onset_s;
      note.offset_beats = next.onset_beats;
    }
  }
  return line;
}

}  // namespace tutti::fingering_planner
