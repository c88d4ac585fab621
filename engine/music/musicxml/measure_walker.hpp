// SPDX-License-Identifier: MIT
#pragma once
// The walk through one part's measures. It keeps MusicXML's time cursor (<divisions>,
// <duration>, <chord/>, <backup>, <forward>) in ticks and collects what sounds: notes (pitch,
// voice, staff, fingering, velocity, ties, grace placement), and the part's directions and
// attributes (tempo, dynamics, pedal, time and key signatures, transposition, staves).
//
// Policies (see also grace_placement.hpp and tie_merge.hpp):
//  - Time is the accumulated cursor; a measure lasts as far as its cursor went, whatever the
//    time signature says (pickups, implicit and incomplete measures just work).
//  - A <backup> past the start of the measure stops there (some exporters overshoot).
//  - Cue notes (<cue/>) move the cursor but do not sound.
//  - Unpitched (percussion) notes sound at the part's <midi-unpitched> key for their
//    <instrument>, else at their <display-step>/<display-octave>; they flag the part.
//  - <alter> is rounded to the nearest semitone (quarter tones); notes whose sounding pitch
//    falls outside MIDI 0..127 are dropped.
//  - Velocity: <sound dynamics> (and the note's dynamics attribute) is a percentage of MIDI 90;
//    without one, dynamics marks (p, mf, ff...) set it; the default is 80.
//  - Tempo: <sound tempo> wherever it appears; a <metronome> with <per-minute> stands in when
//    its direction has no <sound tempo>. <offset sound="yes"> moves a direction's sound.
//  - Pedal: <pedal type="start|stop|change"> marks, or <sound damper-pedal> when the direction
//    has no pedal mark. A pedal still down at the end of the part lifts there.
//  - <transpose> applies to the notes after it (instrument changes mid-part work); the part's
//    transpose_semitones is the first one. Per-staff <transpose>/<key> use staff 1's.
//  - Key signatures are concert keys: a transposing part's written key is transposed back.
//  - Repeats are not expanded: the music is read once, as printed.
//
// Errors name the part and measure: "x.musicxml: part P1 measure 3: <duration> is not a
// number". Loops only ever run over elements, never over duration values.

#include <cstdint>
#include <optional>
#include <pugixml.hpp>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/music/musicxml/score_parts.hpp>
#include <tutti/music/musicxml/tie_merge.hpp>
#include <tutti/music/score.hpp>

namespace tutti::music::musicxml {

// Document-order ordinal of every <note> element (Note::source_index).
using NoteOrdinals = std::unordered_map<const pugi::xml_node_struct*, int>;

struct PartTimeline {
  std::vector<TieMarkedNote> notes;  // Note::part and Note::channel are left to the caller
  std::vector<std::pair<std::int64_t, double>> tempos;  // (tick, microseconds per quarter)
  std::vector<TimeSignature> time_signatures;
  std::vector<KeySignature> key_signatures;
  std::vector<PedalSpan> pedal_spans;  // PedalSpan::part is left to the caller
  // Ticks each of the part's measures lasts, by MeasureSlot::index.
  std::vector<std::pair<std::size_t, std::int64_t>> measure_lengths;
  std::int64_t end_ticks = 0;          // end of the part's last measure
  std::optional<int> first_transpose;  // semitones, from the first <transpose>
  int staves = 1;
  bool unpitched = false;
};

struct WalkSettings {
  const std::string& source;
  int ticks_per_quarter = 480;
  const NoteOrdinals& ordinals;
  // Start tick of every measure (by MeasureSlot::index), aligned across parts; empty = the
  // part's own measures laid end to end (the first pass, which only measures lengths).
  std::span<const std::int64_t> measure_starts;
};

// Every <divisions> value of every part, validated (> 0), for the tick resolution.
Result<std::vector<double>> collect_divisions(const std::vector<PartLayout>& parts,
                                              const std::string& source);

Result<PartTimeline> walk_part(const PartLayout& part, const WalkSettings& settings);

}  // namespace tutti::music::musicxml
