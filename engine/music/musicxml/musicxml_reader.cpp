// SPDX-License-Identifier: MIT
#include <tutti/music/musicxml/musicxml_reader.hpp>
#include <tutti/music/general_midi.hpp>

#include <algorithm>
#include <pugixml.hpp>
#include <tuple>

#include <tutti/core/file_io.hpp>
#include <tutti/music/musicxml/measure_walker.hpp>
#include <tutti/music/musicxml/musicxml_document.hpp>
#include <tutti/music/musicxml/score_parts.hpp>
#include <tutti/music/musicxml/tick_resolution.hpp>

namespace tutti::music {

namespace {

using musicxml::PartLayout;
using musicxml::PartTimeline;


// Channels for parts that state none: one per part in order, skipping the percussion channel.
int automatic_channel(std::size_t part_index) {
  const int channel = static_cast<int>(part_index % 15);
  return channel >= kPercussionChannel ? channel + 1 : channel;
}

// Each part's measures may last differently (an empty measure in one part, a full one in
// another); measure k of every part starts where the longest measure k-1 ended.
Result<std::vector<std::int64_t>> aligned_measure_starts(
    const std::vector<PartTimeline>& first_pass, const std::string& source) {
  std::vector<std::int64_t> longest;
  for (const PartTimeline& part : first_pass) {
    for (const auto& [index, length] : part.measure_lengths) {
      if (index >= longest.size()) longest.resize(index + 1, 0);
      longest[index] = std::max(longest[index], length);
    }
  }
  std::vector<std::int64_t> starts(longest.size() + 1, 0);
  for (std::size_t i = 0; i < longest.size(); ++i) {
    if (longest[i] > musicxml::kMaxTicks - starts[i]) {
      return Error{source + ": the music runs past 2^50 ticks"};
    }
    starts[i + 1] = starts[i] + longest[i];
  }
  return starts;  // one more than the measures: the last entry is the end of the score
}

// TempoMap::set_tempo recomputes every later change, so a hostile file with a million tempo
// marks would take quadratic time; no real score comes near this many.
constexpr std::size_t kMaxTempoChanges = 10'000;

// Tempo changes written once per part become one change each: the first statement at a tick
// wins, and restating the tempo in force changes nothing.
Status add_tempo_changes(Score& score, std::vector<std::pair<std::int64_t, double>> tempos) {
  std::stable_sort(tempos.begin(), tempos.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::pair<std::int64_t, double>> changes;
  double current = TempoMap::kDefaultMicrosecondsPerQuarter;
  std::int64_t last_tick = -1;
  for (const auto& [tick, microseconds] : tempos) {
    if (tick == last_tick) continue;
    last_tick = tick;
    if (microseconds == current) continue;
    changes.emplace_back(tick, microseconds);
    current = microseconds;
  }
  if (changes.size() > kMaxTempoChanges) {
    return Error{score.source + ": more than " + std::to_string(kMaxTempoChanges) +
                 " tempo changes"};
  }
  for (const auto& [tick, microseconds] : changes) score.tempo_map.set_tempo(tick, microseconds);
  return Status::success();
}

// Keeps one of each (tick, value); the order of ticks is finalize_score's business.
template <typename Signature, typename Key>
void remove_duplicates(std::vector<Signature>& signatures, Key key) {
  std::stable_sort(signatures.begin(), signatures.end(),
                   [&](const Signature& a, const Signature& b) { return key(a) < key(b); });
  signatures.erase(
      std::unique(signatures.begin(), signatures.end(),
                  [&](const Signature& a, const Signature& b) { return key(a) == key(b); }),
      signatures.end());
}

Part make_part(const PartLayout& layout, const PartTimeline& timeline) {
  Part part;
  part.id = layout.info.id;
  part.name = layout.info.name;
  part.program = layout.info.program;
  part.channel = layout.info.channel;
  part.transpose_semitones = timeline.first_transpose.value_or(0);
  part.staves = timeline.staves;
  part.percussion = timeline.unpitched || layout.info.channel == kPercussionChannel;
  return part;
}

}  // namespace

Result<Score> read_musicxml(std::span<const std::uint8_t> bytes, const std::string& source_name) {
  auto text = musicxml::musicxml_text(bytes, source_name);
  if (!text) return text.error();
  pugi::xml_document doc;
  if (Status parsed = musicxml::parse_musicxml(*text, pugi::parse_default, doc, source_name);
      !parsed) {
    return parsed.error();
  }

  musicxml::NoteOrdinals ordinals;
  {
    const std::vector<pugi::xml_node> notes = musicxml::note_elements(doc);
    ordinals.reserve(notes.size());
    for (std::size_t i = 0; i < notes.size(); ++i) {
      ordinals.emplace(notes[i].internal_object(), static_cast<int>(i));
    }
  }
  const std::vector<PartLayout> layouts = musicxml::layout_parts(doc.document_element());
  auto divisions = musicxml::collect_divisions(layouts, source_name);
  if (!divisions) return divisions.error();
  const int ticks_per_quarter = musicxml::ticks_per_quarter_for(*divisions);

  // First pass: how long each part makes each measure; second pass: the real walk, with
  // measures aligned across parts.
  std::vector<PartTimeline> timelines;
  for (const PartLayout& layout : layouts) {
    auto timeline = musicxml::walk_part(
        layout, musicxml::WalkSettings{source_name, ticks_per_quarter, ordinals, {}});
    if (!timeline) return timeline.error();
    timelines.push_back(std::move(*timeline));
  }
  auto starts = aligned_measure_starts(timelines, source_name);
  if (!starts) return starts.error();
  for (std::size_t p = 0; p < layouts.size(); ++p) {
    auto timeline = musicxml::walk_part(
        layouts[p], musicxml::WalkSettings{source_name, ticks_per_quarter, ordinals, *starts});
    if (!timeline) return timeline.error();
    timelines[p] = std::move(*timeline);
  }

  Score score;
  score.source = source_name;
  score.tempo_map = TempoMap::with_ticks_per_quarter(ticks_per_quarter);
  std::vector<std::pair<std::int64_t, double>> tempos;
  for (std::size_t p = 0; p < layouts.size(); ++p) {
    PartTimeline& timeline = timelines[p];
    Part part = make_part(layouts[p], timeline);
    const int part_index = static_cast<int>(p);
    const int channel = part.channel >= 0 ? part.channel
                        : part.percussion ? kPercussionChannel
                                          : automatic_channel(p);
    for (Note& note : musicxml::merge_ties(std::move(timeline.notes))) {
      note.part = part_index;
      note.channel = channel;
      part.staves = std::max(part.staves, note.staff);
      score.notes.push_back(note);
    }
    for (PedalSpan span : timeline.pedal_spans) {
      span.part = part_index;
      score.pedal_spans.push_back(span);
    }
    tempos.insert(tempos.end(), timeline.tempos.begin(), timeline.tempos.end());
    score.time_signatures.insert(score.time_signatures.end(), timeline.time_signatures.begin(),
                                 timeline.time_signatures.end());
    score.key_signatures.insert(score.key_signatures.end(), timeline.key_signatures.begin(),
                                timeline.key_signatures.end());
    score.parts.push_back(std::move(part));
  }
  if (Status tempo = add_tempo_changes(score, std::move(tempos)); !tempo) return tempo.error();
  remove_duplicates(score.time_signatures, [](const TimeSignature& t) {
    return std::tuple(t.tick, t.numerator, t.denominator);
  });
  remove_duplicates(score.key_signatures,
                    [](const KeySignature& k) { return std::tuple(k.tick, k.fifths, k.minor); });
  score.end_ticks = starts->back();
  finalize_score(score);
  return score;
}

Result<Score> read_musicxml_file(const std::filesystem::path& path) {
  auto bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  return read_musicxml(*bytes, path.string());
}

}  // namespace tutti::music
