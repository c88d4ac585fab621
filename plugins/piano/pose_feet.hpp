// SPDX-License-Identifier: MIT
#pragma once
// An organist's feet: each frame's Foot components from the plan (pedal_feet.hpp) at t
// (evaluate), then the pedals they hold down, the legs that put each sole's toe point on its
// pedal (two-bone IK from the hip, the sole turned toes-down), and what the toes touch (pose).

#include <tutti/components/foot.hpp>
#include <tutti/ecs/schedule.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/stage/stage.hpp>
#include <tutti/stage/touching.hpp>

namespace tutti::piano {

inline constexpr const char* kFeetSystemName = "organ_feet";

// Phase::evaluate: every PianoRig with feet writes its two Foot components at frame.t_s.
void feet_system(ecs::World& world, const ecs::FrameTime& frame);

// The foot `side` (kRightFoot, kLeftFoot) of the rig's performer, null without pedals.
const components::Foot* foot_of(const ecs::World& world, const PianoRig& rig, int side);

// Turns the pedals the feet hold down (the instrument's pose; nothing without pedals).
void dip_pedals(const ecs::World& world, const PianoRig& rig, model::ModelPose& instrument_pose);

// Poses `body`'s legs (tutti's performer, or a user's character's stand-in; nodes in
// rig.body_nodes) so each foot is where its Foot component has it. After the seated pose.
void pose_feet_on_pedals(const ecs::World& world, PianoRig& rig,
                         const stage::PlacedModel& instrument, stage::PlacedModel& body);

// Each toe on a pedal it holds down, from the model that draws the foot.
void touch_pedals(const ecs::World& world, const PianoRig& rig, stage::Touching& touching);

}  // namespace tutti::piano
