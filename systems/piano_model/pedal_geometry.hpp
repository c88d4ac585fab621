// SPDX-License-Identifier: MIT
#pragma once
// An organ pedalboard's shape, shared by the generated model (content/generator) and the feet
// that play it (plugins/piano): where each pedal stands and where a toe presses it. Frame: the
// pedalboard node's, metres on glTF axes (x across, +Y up, +Z toward the player), origin at the
// pedals' hinge line (the console's front) on the naturals' top, centred under the manual. Each
// pedal's node sits on its hinge, at its top; the pedal runs toward +Z and turns down about +X.

#include <cmath>

#include <tutti/piano_model/keyboard_instruments.hpp>

namespace tutti::piano_model {

struct PedalGeometry {
  static constexpr double kNaturalTopAboveFloor_m = 0.07;
  static constexpr double kNaturalLength_m = 0.62;
  static constexpr double kSharpLength_m = 0.22;
  static constexpr double kSharpRise_m = 0.035;   // a sharp's top above the naturals'
  static constexpr double kPedalWidth_m = 0.024;
  static constexpr double kPedalThickness_m = 0.03;
  // Where the toe presses, from the hinge: a natural in front of the sharps, a sharp near its end.
  static constexpr double kNaturalToe_m = 0.29;
  static constexpr double kSharpToe_m = 0.19;
  // The hinges lie this far under the console, below a kick board this high: the seated
  // player's toes reach the naturals in front of the sharps with the thighs on the bench.
  static constexpr double kUnderConsole_m = 0.08;
  static constexpr double kKickBoardHeight_m = 0.24;
  // How far past the board's middle a foot reaches toward the other end, on a natural and on a
  // sharp (further in); a seated player's hips stay on the bench, so the planner gives what
  // lies beyond to the other foot.
  static constexpr double kFootCrossingNatural_m = 0.40;
  static constexpr double kFootCrossingSharp_m = 0.30;
  // A pedal down: the turn that lowers the toe's point by 12 mm on a natural.
  static constexpr double kDownRad = 0.012 / kNaturalToe_m;
};

inline bool pedal_is_sharp(int key) {
  const int pc = ((key % 12) + 12) % 12;
  return pc == 1 || pc == 3 || pc == 6 || pc == 8 || pc == 10;
}

// Naturals from the pedalboard's lowest key up to `key` (a sharp counts as the natural below).
inline int pedal_natural_index(const Pedalboard& board, int key) {
  int n = -1;
  for (int k = board.lowest_key; k <= key; ++k) n += pedal_is_sharp(k) ? 0 : 1;
  return n;
}

// Across the board (m), 0 at the middle natural: the naturals evenly spaced, a sharp midway
// between the naturals either side of it.
inline double pedal_x_m(const Pedalboard& board, int key) {
  const double middle = 0.5 * static_cast<double>(pedal_natural_index(board, board.highest_key));
  const double spacing = board.natural_spacing_mm / 1000.0;
  const double n = static_cast<double>(pedal_natural_index(board, key));
  return (pedal_is_sharp(key) ? n + 0.5 - middle : n - middle) * spacing;
}

// Whether the right (or left) foot reaches pedal `key` from a seat at the board's middle.
inline bool foot_reaches(const Pedalboard& board, bool right_foot, int key) {
  const double limit = pedal_is_sharp(key) ? PedalGeometry::kFootCrossingSharp_m
                                           : PedalGeometry::kFootCrossingNatural_m;
  const double x = pedal_x_m(board, key);
  return right_foot ? x >= -limit : x <= limit;
}

// The pedal's half width of the whole board (m), to its outer naturals' edges.
inline double pedalboard_half_width_m(const Pedalboard& board) {
  return pedal_x_m(board, board.highest_key) + PedalGeometry::kPedalWidth_m / 2.0;
}

}  // namespace tutti::piano_model
