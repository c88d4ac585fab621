// SPDX-License-Identifier: MIT
#pragma once
// The two hands kept out of each other. Each hand is posed from its own plan, finger by finger;
// where the hands play close together a finger can reach into the other hand: a right thumb that
// has just let go of D4 hangs beside it while the left thumb plays C#4, or two thumbs press
// neighbouring keys. A pianist tucks the free finger away and plays the key where there is room.
//
// After both hands are posed and their pads seated, each finger of either hand whose bones reach
// into the other hand's capsules (hand_capsules.hpp) less kApartMarginMm gives way:
//   - a finger pressing nothing turns aside and lifts at its first joint, as little as takes it
//     clear (damped least squares on measured overlaps), at most kMostYieldSpreadRad aside and
//     kMostYieldLiftRad up; it never turns down toward the keys;
//   - then a pressing finger still in the other hand moves its pad along its key's top, away
//     from it (PadSeater::clear_of): on the surface, inside the outline.
// A pose is a function of the planned components only, so it stays a pure function of t; the
// turn grows from zero as the overlap does. Most frames the hands are apart: their bounding boxes
// tell after one forward pass of each, and a finger whose bones are clear of the other hand is
// not searched.

#include <array>

#include <tutti/ecs/world.hpp>
#include <tutti/piano/pad_seater.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::piano {

inline constexpr double kApartMarginMm = 1.0;
inline constexpr double kMostYieldSpreadRad = 0.5;
inline constexpr double kMostYieldLiftRad = 0.6;

// `hand_models`: the right hand's and the left's posed models (null: that hand is not posed);
// `seated`: their pressing fingers as seat_pads_on_keys left them.
void keep_hands_apart(const ecs::World& world, PianoRig& rig,
                      const std::array<stage::PlacedModel*, 2>& hand_models, const SeatedFingers& seated);

}  // namespace tutti::piano
