// SPDX-License-Identifier: MIT
#include <tutti/cli/score_summary.hpp>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include <tutti/music/general_midi.hpp>
#include <tutti/music/pitch.hpp>

namespace tutti::cli {

ScoreSummary summarize(const music::Score& score, const std::string& format) {
  ScoreSummary summary;
  summary.file = score.source;
  summary.format = format;
  summary.duration_s = score.duration_s();
  summary.ticks_per_quarter = score.tempo_map.ticks_per_quarter();
  summary.tempo_changes = score.tempo_map.changes();
  summary.time_signatures = score.time_signatures;
  summary.key_signatures = score.key_signatures;
  summary.pedal_spans = static_cast<int>(score.pedal_spans.size());

  for (const music::Part& part : score.parts) {
    PartSummary p;
    p.id = part.id;
    p.name = part.name;
    p.program = part.program;
    p.instrument = std::string(music::general_midi_program_name(part.program));
    p.channel = part.channel;
    p.transpose_semitones = part.transpose_semitones;
    p.staves = part.staves;
    p.percussion = part.percussion;
    summary.parts.push_back(std::move(p));
  }
  bool first = true;
  for (const music::Note& note : score.notes) {
    ++summary.notes;
    if (note.finger != 0) ++summary.fingered_notes;
    if (first) summary.first_onset_s = note.onset_s;
    first = false;
    summary.last_offset_s = std::max(summary.last_offset_s, note.offset_s);
    if (note.part < 0 || static_cast<std::size_t>(note.part) >= summary.parts.size()) continue;
    PartSummary& p = summary.parts[static_cast<std::size_t>(note.part)];
    ++p.notes;
    if (note.finger != 0) ++p.fingered_notes;
    p.lowest = std::min(p.lowest.value_or(note.pitch), note.pitch);
    p.highest = std::max(p.highest.value_or(note.pitch), note.pitch);
  }
  return summary;
}

namespace {
std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string range_text(const PartSummary& p) {
  if (!p.lowest) return "-";
  return music::pitch_name(*p.lowest) + ".." + music::pitch_name(*p.highest) + " (" +
         std::to_string(*p.lowest) + ".." + std::to_string(*p.highest) + ")";
}
}  // namespace

std::string summary_text(const ScoreSummary& s) {
  std::ostringstream out;
  out << s.file << " (" << s.format << ")\n";
  out << "  notes: " << s.notes;
  if (s.fingered_notes > 0) out << " (" << s.fingered_notes << " with fingering)";
  out << "\n  duration: " << fixed(s.duration_s, 3) << " s (notes " << fixed(s.first_onset_s, 3)
      << " .. " << fixed(s.last_offset_s, 3) << " s)\n";
  out << "  timing: "
      << (s.ticks_per_quarter > 0 ? std::to_string(s.ticks_per_quarter) + " ticks per quarter"
                                  : std::string("SMPTE"))
      << "\n";
  out << "  tempo:";
  const std::size_t shown = std::min<std::size_t>(s.tempo_changes.size(), 8);
  for (std::size_t i = 0; i < shown; ++i) {
    out << (i ? ", " : " ") << fixed(s.tempo_changes[i].bpm(), 2) << " BPM at "
        << fixed(s.tempo_changes[i].seconds, 3) << " s";
  }
  if (s.tempo_changes.size() > shown) out << ", ... (" << s.tempo_changes.size() << " changes)";
  out << "\n";
  if (!s.time_signatures.empty()) {
    out << "  time signatures:";
    for (std::size_t i = 0; i < std::min<std::size_t>(s.time_signatures.size(), 8); ++i) {
      const auto& ts = s.time_signatures[i];
      out << (i ? ", " : " ") << ts.numerator << "/" << ts.denominator << " at "
          << fixed(ts.seconds, 3) << " s";
    }
    if (s.time_signatures.size() > 8) out << ", ...";
    out << "\n";
  }
  if (s.pedal_spans > 0) out << "  sustain pedal: " << s.pedal_spans << " presses\n";
  out << "  parts: " << s.parts.size() << "\n";
  for (std::size_t i = 0; i < s.parts.size(); ++i) {
    const PartSummary& p = s.parts[i];
    out << "    [" << i << "] " << (p.name.empty() ? p.id : p.name) << ": "
        << (p.percussion ? std::string("percussion")
                         : p.instrument + " (program " + std::to_string(p.program) + ")");
    if (p.channel >= 0) out << ", channel " << p.channel + 1;
    if (p.transpose_semitones != 0) out << ", transposes " << p.transpose_semitones;
    out << ", " << p.notes << " notes, range " << range_text(p);
    if (p.fingered_notes > 0) out << ", " << p.fingered_notes << " fingered";
    out << "\n";
  }
  return out.str();
}

std::string summary_json(const ScoreSummary& s) {
  using Json = nlohmann::ordered_json;
  Json root;
  root["file"] = s.file;
  root["format"] = s.format;
  root["notes"] = s.notes;
  root["fingered_notes"] = s.fingered_notes;
  root["duration_s"] = s.duration_s;
  root["first_onset_s"] = s.first_onset_s;
  root["last_offset_s"] = s.last_offset_s;
  root["ticks_per_quarter"] = s.ticks_per_quarter;
  Json parts = Json::array();
  for (const PartSummary& p : s.parts) {
    Json part;
    part["id"] = p.id;
    part["name"] = p.name;
    part["program"] = p.program;
    part["instrument"] = p.instrument;
    part["channel"] = p.channel >= 0 ? Json(p.channel) : Json(nullptr);
    part["transpose_semitones"] = p.transpose_semitones;
    part["staves"] = p.staves;
    part["percussion"] = p.percussion;
    part["notes"] = p.notes;
    part["fingered_notes"] = p.fingered_notes;
    part["lowest"] = p.lowest ? Json(*p.lowest) : Json(nullptr);
    part["highest"] = p.highest ? Json(*p.highest) : Json(nullptr);
    parts.push_back(std::move(part));
  }
  root["parts"] = std::move(parts);
  Json tempo = Json::array();
  for (const auto& change : s.tempo_changes) {
    tempo.push_back(
        Json{{"tick", change.tick}, {"seconds", change.seconds}, {"bpm", change.bpm()}});
  }
  root["tempo_changes"] = std::move(tempo);
  Json times = Json::array();
  for (const auto& ts : s.time_signatures) {
    times.push_back(Json{{"tick", ts.tick},
                         {"seconds", ts.seconds},
                         {"numerator", ts.numerator},
                         {"denominator", ts.denominator}});
  }
  root["time_signatures"] = std::move(times);
  Json keys = Json::array();
  for (const auto& ks : s.key_signatures) {
    keys.push_back(Json{
        {"tick", ks.tick}, {"seconds", ks.seconds}, {"fifths", ks.fifths}, {"minor", ks.minor}});
  }
  root["key_signatures"] = std::move(keys);
  root["pedal_spans"] = s.pedal_spans;
  // Track names in old MIDI files are often Latin-1; replace invalid UTF-8 rather than fail.
  return root.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace tutti::cli
