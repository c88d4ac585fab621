// SPDX-License-Identifier: MIT
#include <tutti/music/meter.hpp>

#include <cmath>

namespace tutti::music {

int bar_at_beats(const Score& score, double beats) {
  double bar_start = 0.0;
  int bar = 1;
  double bar_length = 4.0;
  for (const TimeSignature& ts : score.time_signatures) {
    const double at = score.tempo_map.beats_at(static_cast<double>(ts.tick));
    if (at > beats) break;
    const double bars = std::floor((at - bar_start) / bar_length + 1e-9);
    bar += static_cast<int>(bars);
    bar_start += bars * bar_length;
    if (at > bar_start + 1e-9) {  // a change mid-bar starts a new bar
      ++bar;
      bar_start = at;
    }
    bar_length = ts.denominator > 0 ? 4.0 * ts.numerator / ts.denominator : 4.0;
  }
  return bar + static_cast<int>(std::floor((beats - bar_start) / bar_length + 1e-9));
}

double beat_length_at(const Score& score, double beats) {
  const TimeSignature* in_force = nullptr;
  for (const TimeSignature& ts : score.time_signatures) {
    if (score.tempo_map.beats_at(static_cast<double>(ts.tick)) > beats + 1e-9) break;
    in_force = &ts;
  }
  if (in_force == nullptr || in_force->denominator <= 0) return 1.0;
  const double unit = 4.0 / in_force->denominator;
  const bool compound =
      in_force->denominator >= 8 && in_force->numerator > 3 && in_force->numerator % 3 == 0;
  return compound ? 3.0 * unit : unit;
}

}  // namespace tutti::music
