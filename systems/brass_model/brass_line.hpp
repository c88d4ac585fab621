// SPDX-License-Identifier: MIT
#pragma once
// One player's line on a brass instrument, as the brass fingering planner leaves it: monophonic
// notes in time order (a part's chords split into voices; overlaps trimmed), each with its
// written and sounding pitch and the fingering chosen. Input of the motion, mouth and breath
// planning. Notes outside the instrument's range stay in the line with playable = false.

#include <string>
#include <vector>

#include <tutti/brass_model/instrument.hpp>

namespace tutti::brass_model {

struct LineNote {
  int score_index = -1;  // into Score::notes
  double onset_s = 0.0;
  double offset_s = 0.0;     // > onset_s unless the note has no duration; <= the next onset
  double onset_beats = 0.0;  // quarter notes from the start (Score::Note)
  double offset_beats = 0.0;
  int sounding = 60;  // MIDI key
  int written = 60;   // MIDI key as written for the instrument
  int velocity = 64;
  bool playable = true;    // in range; false = reported and left unplayed (no fingering)
  int fingering = -1;      // index into Instrument::chart, -1 = none
  bool alternate = false;  // fingering is not the standard one for this pitch
};

// When a player may start changing to the next note (slide move, valve change): from the end of
// the previous note, or — legato, no rest — in its last part: release_fraction of it, at most
// release_max_s. The fingering planner prices moves with it and the motion uses the same window.
struct ChangeWindow {
  double release_fraction = 0.25;
  double release_max_s = 0.1;
};

// Start and length of the window before `to`'s onset.
inline double change_window_start_s(const LineNote& from, const LineNote& to,
                                    const ChangeWindow& w) {
  const double end = from.offset_s < to.onset_s ? from.offset_s : to.onset_s;
  const double held = end > from.onset_s ? end - from.onset_s : 0.0;
  const double early =
      w.release_fraction * held < w.release_max_s ? w.release_fraction * held : w.release_max_s;
  return end - early;
}
inline double change_window_s(const LineNote& from, const LineNote& to, const ChangeWindow& w) {
  return to.onset_s - change_window_start_s(from, to, w);
}

struct BrassLine {
  std::string part_name;
  int part = -1;  // Score part index
  int voice = 0;  // 0 = top voice of the part's chords, 1 = the next one down, ...
  const Instrument* instrument = nullptr;
  std::vector<LineNote> notes;
};

}  // namespace tutti::brass_model
