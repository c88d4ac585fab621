// SPDX-License-Identifier: MIT
#pragma once
// Sampled instruments take time to speak: in Debian's General MIDI font a piano note is heard
// about 2 ms after its note-on, a trumpet note 5-20 ms after, a trombone note 20-80 ms after: the
// recorded attack. A key reaching its bottom or a player's tongue, valve or slide, on screen,
// lands on the beat, and so does the sound of a real instrument; notation players schedule
// samples early by their attack. This does the same, with the attack of every (program, key,
// velocity / 8) measured from the sound font itself:
//
//   render the note alone from silence with FluidSynth, find it with the onset detector, and send
//   its note-on that much earlier (for a slur, the old note's note-off with it). A struck note
//   (GM programs 0-15: pianos, chromatic percussion) is heard where its energy jumps
//   (energy_rise.hpp), which the detector's -6 dB point places some 7 ms later; a blown note
//   swells and is heard at the detector's point.
//
// The attack is measured with the same ear `tutti sync-report` uses, on the note alone; the
// report then listens to the whole mix, where the other players and the old note's release
// mask it differently.
//
// Deterministic (offline rendering). Percussion channels stay; a note never moves before its key
// was last released on its channel, a line's note (nothing else sounding) never into the note
// before it, and a slur (the old note released at the new one's frame) keeps half the old note.

#include <filesystem>
#include <span>
#include <vector>

#include <tutti/audio/onset_detection.hpp>
#include <tutti/audio/synth_events.hpp>
#include <tutti/core/result.hpp>

namespace tutti::audio {

// Whether a General MIDI program's notes are struck (programs 0-15: pianos, chromatic
// percussion): heard where their energy jumps rather than at the detector's point.
bool is_struck_program(int program);

struct SampledNote {
  int program = 56;
  int key = 60;
  int velocity = 80;
};

struct AttackOptions {
  double max_advance_s = 0.100;  // never earlier than this
  OnsetOptions onsets;           // the ear that hears the attack
};

// Seconds from each note-on until the note speaks (see above); 0 for a note that stays silent.
// Errors: the sound font does not load.
Result<std::vector<double>> measure_attack_times(const std::filesystem::path& sound_font,
                                                 std::span<const SampledNote> notes,
                                                 int sample_rate,
                                                 const AttackOptions& options = {});

struct AttackCompensation {
  int notes = 0;  // melodic note-ons seen
  int moved = 0;  // moved earlier by at least one 64-frame block
  double mean_advance_s = 0.0;
  double max_advance_s = 0.0;
};

// Moves every melodic note-on of `timeline` earlier by its measured attack (on 64-frame blocks,
// within the limits above). Events stay ordered.
Result<AttackCompensation> compensate_attacks(SynthTimeline& timeline,
                                              const std::filesystem::path& sound_font,
                                              const AttackOptions& options = {});

}  // namespace tutti::audio
