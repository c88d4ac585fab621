// SPDX-License-Identifier: MIT
#pragma once
// Spelled pitch names <-> MIDI keys. Middle C is "C4" = 60 (scientific pitch notation).
// Accepted spellings: a letter A-G (either case), any run of '#' or 'b' (also "x" for a
// double sharp), then an octave number (may be negative: "C-1" = 0).

#include <optional>
#include <string>
#include <string_view>

namespace tutti::music {

// MIDI key of a step/alter/octave triple (step is 'A'..'G'). nullopt outside 0..127.
std::optional<int> midi_key(char step, int alter, int octave);

// Parses "C4", "F#5", "Bb3", "Ebb2", "Cx4", "C-1". nullopt on anything else or out of 0..127.
std::optional<int> parse_pitch_name(std::string_view name);

// "C4", "C#4", ... using sharps. Precondition: 0 <= key <= 127.
std::string pitch_name(int key);

// True for the five black keys of each octave.
constexpr bool is_black_key(int key) {
  const int pc = ((key % 12) + 12) % 12;
  return pc == 1 || pc == 3 || pc == 6 || pc == 8 || pc == 10;
}

}  // namespace tutti::music
