// SPDX-License-Identifier: MIT
#pragma once
// Phase::pose for the brass family: components → the models' poses. Valves go down by their
// press × travel, the slide out by its extension; the instrument hangs from the player's lips;
// the body takes the seated legs, the ensemble's motion (or the breathing chest), the mouth's
// morphs, the fingers' grip curls, and two-bone IK puts each hand on the instrument's grip.

#include <tutti/ecs/schedule.hpp>
#include <tutti/ecs/world.hpp>

namespace tutti::brass {

void brass_skeleton_system(ecs::World& world, const ecs::FrameTime& frame);

inline constexpr const char* kBrassSkeletonSystemName = "brass_skeleton";

}  // namespace tutti::brass
