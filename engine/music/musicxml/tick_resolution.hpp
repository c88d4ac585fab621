// SPDX-License-Identifier: MIT
#pragma once
// One tick resolution for the whole score. MusicXML measures time in <divisions> per quarter
// note, which may differ between parts and change mid-part; every value is scaled to a common
// ticks-per-quarter so positions stay exact integers.
//
// Policy: ticks_per_quarter = lcm(480, every divisions value). The 480 keeps a usable resolution
// when a file says divisions=1 (grace notes get a 32nd of a quarter, ppq/8) and matches MIDI
// habits; the lcm keeps every duration exact. When that exceeds kMaxTicksPerQuarter (or a
// divisions value is not a whole number), the fallback is kFallbackTicksPerQuarter = 960 * 693
// = 665280, divisible by 1..12, 14, 15, 16, 32 and 64, and durations are rounded to it.

#include <cstdint>
#include <optional>
#include <span>

namespace tutti::music::musicxml {

inline constexpr std::int64_t kMaxTicksPerQuarter = 1'000'000;
inline constexpr int kFallbackTicksPerQuarter = 960 * 693;
inline constexpr int kBaseTicksPerQuarter = 480;
// Positions beyond this are refused: an absurd score, and far from int64 overflow.
inline constexpr std::int64_t kMaxTicks = std::int64_t{1} << 50;

// Precondition: every value is finite and > 0.
int ticks_per_quarter_for(std::span<const double> divisions_values);

// Ticks for a duration given in divisions, rounded to the nearest tick; nullopt if the result is
// negative or beyond kMaxTicks. Exact when ticks_per_quarter is a multiple of divisions.
std::optional<std::int64_t> divisions_to_ticks(double duration, double divisions,
                                               int ticks_per_quarter);

}  // namespace tutti::music::musicxml
