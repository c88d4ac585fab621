// SPDX-License-Identifier: MIT
#pragma once
// What MusicXML's marks mean in numbers: dynamics as MIDI velocities, metronome marks as
// tempo, <time> as a signature, written keys of transposing parts as concert keys.

#include <optional>
#include <pugixml.hpp>
#include <string_view>
#include <utility>

namespace tutti::music::musicxml {

// Velocity when a file states no dynamics: between mf and f.
inline constexpr int kDefaultVelocity = 80;

// <sound dynamics> and the note's dynamics attribute: a percentage of the MIDI forte velocity
// 90 ("100" -> 90), clamped to 1..127. nullopt for text that is not a number >= 0.
std::optional<int> velocity_from_percent(std::string_view percent_text);

// <dynamics> marks: "pp" -> 33, "mf" -> 80, "f" -> 96, ... nullopt for accents (sf, fz...).
std::optional<int> velocity_of_dynamics_mark(std::string_view mark);

// Quarter notes per minute of a <metronome> ("dotted quarter = 100" -> 150); nullopt for metric
// modulations (note = note) and marks without a number.
std::optional<double> metronome_bpm(pugi::xml_node metronome);

// (numerator, denominator) of a <time>: composite beats ("3+2"/8 -> 5/8) and several pairs
// (2/4 + 3/8 -> 7/8) add up over the common denominator. nullopt for senza misura and
// anything unreadable.
std::optional<std::pair<int, int>> time_signature_fraction(pugi::xml_node time);

// A transposing part writes its key transposed (a part in Bb: D major for concert C major).
// Each semitone adds 7 fifths (mod 12); the result is the spelling with at most 7 accidentals.
int concert_fifths(int written_fifths, int transpose_semitones);

}  // namespace tutti::music::musicxml
