// SPDX-License-Identifier: MIT
#pragma once
// Phase::pose for the piano family: components → the models' poses. Each finger's key turns by
// its press depth × the key's dip; the hand models sit at their Hand position in the piano's
// keyboard frame with the finger bones set from the Finger angles (content/generator/README.md's
// posing contract); the seated pianist leans in and reaches the hand models' wrists (two-bone IK).

#include <tutti/ecs/schedule.hpp>
#include <tutti/ecs/world.hpp>

namespace tutti::piano {

void piano_skeleton_system(ecs::World& world, const ecs::FrameTime& frame);

inline constexpr const char* kPianoSkeletonSystemName = "piano_skeleton";

}  // namespace tutti::piano
