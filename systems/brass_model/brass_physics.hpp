// SPDX-License-Identifier: MIT
#pragma once
// The acoustics the fingering charts are derived from: the open harmonic series, how much a
// valve combination lowers it (tube lengths add, so combinations come out sharp), and where a
// U-shaped slide must be for a given lowering. Pure functions, no data files.

#include <cstdint>
#include <span>

#include <tutti/brass_model/instrument.hpp>

namespace tutti::brass_model {

inline constexpr double kSpeedOfSoundMPerS = 343.0;  // dry air, 20 °C

// Interval of partial n above the fundamental, in equal-tempered semitones: 12·log2(n).
double partial_semitones(int partial);
// The nearest whole number of semitones (the note a chart names the partial by).
int partial_nominal_semitones(int partial);
// How far partial n lies from that note, in cents (+ = sharp): 5 → −13.7, 7 → −31.2, 9 → +3.9.
double partial_cents(int partial);

// How far valve combination `mask` (bit i = valves[i] down) lowers the open series, in
// semitones, from the tube lengths: each valve alone adds the loop that lowers by its
// lowers_semitones, so the combination adds the sum of loops to the open tube and comes out
// sharp (1+3 on a trumpet: 4.70 for a nominal 5). A side-switching valve (double horn thumb)
// scales the open tube and every loop by 2^(s/12).
double combination_lowering_semitones(std::span<const ValveSpec> valves, std::uint8_t mask);
// What a chart calls it: the sum of the valves' lowerings, rounded (1+3 → 5).
int combination_nominal_semitones(std::span<const ValveSpec> valves, std::uint8_t mask);

// Effective length of an open tube whose fundamental (partial 1) sounds at MIDI key `sounding`:
// half a wavelength, c / (2·f). A B♭ tenor trombone (B♭1, 58.27 Hz): 2943 mm.
double acoustic_length_mm(int sounding);
// A U-slide adds twice its extension to the tube, so lowering a tube of length L by s semitones
// takes an extension of L·(2^(s/12) − 1)/2 (negative s: a negative extension).
double slide_extension_mm(double tube_length_mm, double semitones);
// The inverse: the lowering, in semitones, of an extension.
double slide_semitones(double tube_length_mm, double extension_mm);

}  // namespace tutti::brass_model
