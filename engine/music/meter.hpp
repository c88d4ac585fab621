// SPDX-License-Identifier: MIT
#pragma once
// Bars and beats from a score's time signatures: which bar a moment falls in (for messages), and
// how long a beat is there (for rules stated in beats, such as where a player breathes).

#include <tutti/music/score.hpp>

namespace tutti::music {

// 1-based bar containing `beats` (quarter notes from the start). A time signature that changes
// mid-bar starts a new bar. Without time signatures, 4/4.
int bar_at_beats(const Score& score, double beats);

// Length of one beat, in quarter notes, under the time signature in force at `beats`: the
// denominator's note (3/4 → 1, 2/2 → 2, 3/8 → 0.5), except compound meters (6/8, 9/8, 12/8,
// 6/16 ...), counted in dotted beats (6/8 → 1.5). Without time signatures, 1.
double beat_length_at(const Score& score, double beats);

}  // namespace tutti::music
