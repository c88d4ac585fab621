// SPDX-License-Identifier: MIT
#pragma once
// The score model every reader produces and every planner consumes. Plain data: readers fill it,
// `finalize_score` sorts it and derives seconds/beats from ticks, nobody else mutates it.
//
// Conventions:
//  - `pitch` is the *sounding* MIDI key 0..127. The written pitch of a transposing part is
//    `pitch - part.transpose_semitones`.
//  - Ticks are the file's own time unit (MIDI ticks, or MusicXML divisions scaled to one common
//    resolution); seconds and beats (quarter notes) are derived through `tempo_map`.
//  - Indices (`Note::part`, `PedalSpan::part`) index `Score::parts`.

#include <cstdint>
#include <string>
#include <vector>

#include <tutti/music/tempo_map.hpp>

namespace tutti::music {

enum class Hand : std::int8_t { unknown = 0, right = 1, left = 2 };

struct Note {
  int pitch = 60;  // sounding MIDI key, 0..127
  std::int64_t onset_ticks = 0;
  std::int64_t offset_ticks = 0;  // >= onset_ticks
  double onset_s = 0.0;
  double offset_s = 0.0;
  double onset_beats = 0.0;  // quarter notes from the start
  double offset_beats = 0.0;
  int velocity = 64;          // 1..127
  int release_velocity = 64;  // 0..127 (MIDI note-off velocity)
  int part = 0;
  int channel = 0;  // MIDI channel 0..15
  int voice = 0;    // 1-based voice within the part, 0 = not stated
  int staff = 0;    // 1-based staff within the part, 0 = not stated
  // Fingering, when the file carries it: 1 = thumb .. 5 = little finger, 0 = none.
  int finger = 0;
  // A finger substitution while the key is held (PIG "3_1": strike with 3, hold with 1), else 0.
  int finger_substitute = 0;
  // Every finger of a PIG substitution in order ("2_4_5": 2, 4, 5; `finger` the first and
  // `finger_substitute` the last), when it has more than two; empty otherwise.
  std::vector<int> finger_sequence;
  Hand hand = Hand::unknown;
  bool grace = false;
  // Where the note came from, so writers can annotate the original file: the ordinal of the
  // <note> element (MusicXML), of the note-on event (MIDI) or of the line (PIG). -1 = none.
  int source_index = -1;
};

struct Part {
  std::string id;               // MusicXML part id, or "track<T>-ch<C>" for MIDI
  std::string name;             // human name, as the file writes it; may be empty
  int program = 0;              // General MIDI program 0..127
  int channel = -1;             // MIDI channel 0..15, -1 = not stated
  int track = -1;               // MIDI track index, -1 = not from a MIDI track
  int transpose_semitones = 0;  // sounding = written + transpose_semitones
  int staves = 1;
  bool percussion = false;  // GM channel 10 or unpitched MusicXML part
};

struct TimeSignature {
  std::int64_t tick = 0;
  double seconds = 0.0;
  int numerator = 4;
  int denominator = 4;
};

struct KeySignature {
  std::int64_t tick = 0;
  double seconds = 0.0;
  int fifths = 0;  // -7..7, negative = flats
  bool minor = false;
};

// Sustain (damper) pedal held down, per part.
struct PedalSpan {
  int part = 0;
  std::int64_t onset_ticks = 0;
  std::int64_t offset_ticks = 0;
  double onset_s = 0.0;
  double offset_s = 0.0;
};

enum class TextKind : std::int8_t {
  text,
  copyright,
  track_name,
  instrument_name,
  lyric,
  marker,
  cue_point,
  other
};

struct TextEvent {
  std::int64_t tick = 0;
  double seconds = 0.0;
  TextKind kind = TextKind::text;
  int track = -1;
  std::string text;
};

struct Score {
  std::string source;  // file name the score was read from, for messages
  TempoMap tempo_map;
  std::vector<Part> parts;
  std::vector<Note> notes;  // sorted by (onset_ticks, pitch, part) after finalize_score
  std::vector<TimeSignature> time_signatures;  // sorted by tick
  std::vector<KeySignature> key_signatures;    // sorted by tick
  std::vector<PedalSpan> pedal_spans;          // sorted by (part, onset)
  std::vector<TextEvent> texts;                // sorted by tick
  // A PIG file's note lines as read: the text before the finger column (id, onset, offset,
  // spelled pitch, velocities, channel, with their spacing) and the line each came from
  // (Note::source_index), in file order.
  // write_pig gives them back unchanged but for the finger, so line-by-line tools can compare.
  struct PigRow {
    int line = 0;
    std::string columns;
  };
  std::vector<PigRow> pig_rows;
  // The end of the piece: the last event of any kind (end-of-track, last barline), never before
  // the last note's offset.
  std::int64_t end_ticks = 0;
  double end_s = 0.0;

  double duration_s() const { return end_s; }
};

// Sorts every list, fills every seconds/beats field from ticks and the tempo map, and raises
// end_ticks to cover the last note. Readers call it last.
void finalize_score(Score& score);

}  // namespace tutti::music
