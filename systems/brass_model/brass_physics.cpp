// SPDX-License-Identifier: MIT
#include <tutti/brass_model/brass_physics.hpp>

#include <cmath>

namespace tutti::brass_model {

double partial_semitones(int partial) { return 12.0 * std::log2(double(partial)); }

int partial_nominal_semitones(int partial) {
  return static_cast<int>(std::lround(partial_semitones(partial)));
}

double partial_cents(int partial) {
  return 100.0 * (partial_semitones(partial) - partial_nominal_semitones(partial));
}

double combination_lowering_semitones(std::span<const ValveSpec> valves, std::uint8_t mask) {
  double side = 1.0;   // open tube of the side in use, relative to the main open tube
  double loops = 0.0;  // the lowered valves' loops, relative to that side's open tube
  for (std::size_t i = 0; i < valves.size() && i < 8; ++i) {
    if ((mask & (1u << i)) == 0) continue;
    const double ratio = std::exp2(valves[i].lowers_semitones / 12.0);
    if (valves[i].switches_side) {
      side *= ratio;
    } else {
      loops += ratio - 1.0;
    }
  }
  return 12.0 * std::log2(side * (1.0 + loops));
}

int combination_nominal_semitones(std::span<const ValveSpec> valves, std::uint8_t mask) {
  double sum = 0.0;
  for (std::size_t i = 0; i < valves.size() && i < 8; ++i) {
    if ((mask & (1u << i)) != 0) sum += valves[i].lowers_semitones;
  }
  return static_cast<int>(std::lround(sum));
}

double acoustic_length_mm(int sounding) {
  const double hz = 440.0 * std::exp2((sounding - 69) / 12.0);
  return 1000.0 * kSpeedOfSoundMPerS / (2.0 * hz);
}

double slide_extension_mm(double tube_length_mm, double semitones) {
  return tube_length_mm * (std::exp2(semitones / 12.0) - 1.0) / 2.0;
}

double slide_semitones(double tube_length_mm, double extension_mm) {
  return 12.0 * std::log2(1.0 + 2.0 * extension_mm / tube_length_mm);
}

}  // namespace tutti::brass_model
