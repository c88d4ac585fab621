// SPDX-License-Identifier: MIT
#pragma once
// The ECS side of brass motion: a brass player's performer entity carries a handle to its
// immutable planned motion and breathing; every frame (Phase::evaluate) brass_pose_system writes
// the performer's Mouth and Breath, and the Valve / Slide of the instrument entity it plays.
//
// Wiring: performer entity: BrassPlayerMotionHandle, components::Mouth, components::Breath.
// Instrument entity: components::Instrument with `performer` = that performer, and
// components::Valve and/or components::Slide. Stale links or a null plan leave components as
// they are.

#include <memory>

#include <tutti/brass_motion/brass_motion_plan.hpp>
#include <tutti/brass_motion/breath_plan.hpp>
#include <tutti/ecs/schedule.hpp>
#include <tutti/ecs/world.hpp>

namespace tutti::brass_motion {

// Everything needed to pose one brass player; built once after planning, then immutable.
struct BrassPlayerMotion {
  BrassMotionPlan motion;
  BreathPlan breaths;
};

// Component on the performer entity: a shared handle to immutable plan data.
struct BrassPlayerMotionHandle {
  std::shared_ptr<const BrassPlayerMotion> motion;
};

// Allocation-free per frame; reads only plan data and the links above.
void brass_pose_system(ecs::World& world, const ecs::FrameTime& frame);

inline constexpr const char* kBrassMotionSystemName = "brass_motion";
void register_brass_motion(ecs::Schedule& schedule);

}  // namespace tutti::brass_motion
