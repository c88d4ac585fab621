// SPDX-License-Identifier: MIT
#pragma once
// An organist's feet at time t (pedal_feet.hpp's plan): the pedals they hold down, the legs that
// put each sole's toe point on its pedal (two-bone IK from the hip, the sole turned toes-down),
// and what the toes touch.

#include <tutti/piano/piano_components.hpp>
#include <tutti/stage/stage.hpp>
#include <tutti/stage/touching.hpp>

namespace tutti::piano_family {

// Turns the pedals the feet hold down at `t` (the instrument's pose; nothing without pedals).
void dip_pedals(const PianoRig& rig, double t, model::ModelPose& instrument_pose);

// Poses `body`'s legs (tutti's performer, or a user's character's stand-in; nodes in
// rig.body_nodes) so each foot is where the plan has it at `t`. After the seated pose.
void pose_feet_on_pedals(PianoRig& rig, const stage::PlacedModel& instrument,
                         stage::PlacedModel& body, double t);

// Each toe on a pedal it holds down, from the model that draws the foot.
void touch_pedals(const PianoRig& rig, double t, stage::Touching& touching);

}  // namespace tutti::piano_family
