// SPDX-License-Identifier: MIT
#pragma once
// The valves of a valved brass instrument (or a trombone's trigger), on the instrument entity:
// how far each is pressed at the current frame. Written every frame by the brass pose system
// (Phase::evaluate); read by posing (piston nodes, the player's fingers).

#include <array>
#include <cstdint>

namespace tutti::components {

struct Valve {
  static constexpr int kMax = 6;
  std::array<float, kMax> press{};  // per valve, in the instrument file's order: 0 = up .. 1 = down
  std::uint8_t count = 0;           // valves the instrument has (the rest stay 0)
};

}  // namespace tutti::components
