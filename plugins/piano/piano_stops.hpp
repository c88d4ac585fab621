// SPDX-License-Identifier: MIT
#pragma once
// The stops a keyboard player reaches (stage/contact_detector.hpp): a key at its bed under a
// finger and back up, an organ pedal at its bottom under a foot and back up. The value of each is
// the MIDI key.

#include <memory>
#include <span>

#include <tutti/stage/contact_detector.hpp>

namespace tutti::piano {

std::span<const stage::StopKind* const> keyboard_stop_kinds();
// Watches every Finger, then every Foot, each in spawn order; nullptr when the world has none.
std::unique_ptr<stage::StopTracker> track_keyboard_stops(ecs::World& world);

}  // namespace tutti::piano
