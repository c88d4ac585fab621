// SPDX-License-Identifier: MIT
#pragma once
// What `tutti info` reports about a score, computed once and printed as text or JSON.

#include <optional>
#include <string>
#include <vector>

#include <tutti/music/score.hpp>

namespace tutti::cli {

struct PartSummary {
  std::string id;
  std::string name;
  int program = 0;
  std::string instrument;  // General MIDI name of `program`
  int channel = -1;
  int transpose_semitones = 0;
  int staves = 1;
  bool percussion = false;
  int notes = 0;
  int fingered_notes = 0;
  std::optional<int> lowest;  // sounding MIDI key; empty when the part has no notes
  std::optional<int> highest;
};

struct ScoreSummary {
  std::string file;
  std::string format;
  int notes = 0;
  int fingered_notes = 0;
  double duration_s = 0.0;
  double first_onset_s = 0.0;
  double last_offset_s = 0.0;
  int ticks_per_quarter = 0;  // 0 for SMPTE timing
  std::vector<PartSummary> parts;
  std::vector<music::TempoChange> tempo_changes;
  std::vector<music::TimeSignature> time_signatures;
  std::vector<music::KeySignature> key_signatures;
  int pedal_spans = 0;
};

ScoreSummary summarize(const music::Score& score, const std::string& format);

std::string summary_text(const ScoreSummary& summary);
// Keys in a fixed order; the same score always gives the same bytes.
std::string summary_json(const ScoreSummary& summary);

}  // namespace tutti::cli
