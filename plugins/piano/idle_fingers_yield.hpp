// SPDX-License-Identifier: MIT
#pragma once
// Fingers that press nothing give way to the other hand. Each hand is posed from its own plan,
// finger by finger; a finger that has just let go (or waits for its next key) keeps its place
// beside the hand, and where the two hands play close together it can hang where the other hand
// plays: a right thumb that left D4 beside a left thumb now on C#4. A pianist tucks it away.
//
// After both hands are posed and their pads seated, each finger of either hand that presses no
// key and whose bones reach into the other hand's capsules (hand_capsules.hpp) less
// kYieldMarginMm turns aside and lifts at its first joint, as little as takes it clear (damped
// least squares on measured overlaps), at most kMostYieldSpreadRad aside and kMostYieldLiftRad up.
// It never turns down toward the keys. A pose is a function of the planned components only, so
// it stays a pure function of t; the turn grows from zero as the overlap does.

#include <array>

#include <tutti/ecs/world.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::piano_family {

inline constexpr double kYieldMarginMm = 1.0;
inline constexpr double kMostYieldSpreadRad = 0.5;
inline constexpr double kMostYieldLiftRad = 0.6;

// `hand_models`: the right hand's and the left's posed models (null: that hand is not posed).
void idle_fingers_yield(const ecs::World& world, PianoRig& rig,
                        const std::array<stage::PlacedModel*, 2>& hand_models);

}  // namespace tutti::piano_family
