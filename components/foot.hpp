// SPDX-License-Identifier: MIT
#pragma once
// One foot of a player on a pedalboard (an organist's): the pedal it is over or moving to, how
// far it holds that pedal down, and how high its sole is. Written every frame by the keyboard
// family's feet system (Phase::evaluate), read by posing, the contact detector and check-pose.

#include <tutti/components/hand_side.hpp>
#include <tutti/ecs/entity.hpp>

namespace tutti::components {

struct Foot {
  ecs::Entity performer = ecs::Entity::null;  // whose foot
  HandSide side = HandSide::right;            // right or left foot
  int from_key = -1;    // the pedal (MIDI key) the foot is over or leaving; -1 = none to play
  int to_key = -1;      // the pedal it is moving to (== from_key when still)
  double travel = 0.0;  // 0 over from_key .. 1 over to_key
  double press_depth = 0.0;  // how far it holds from_key down: 0 = up .. 1 = the pedal's bottom
  int key = -1;              // the pedal held down (press_depth > 0), else -1
  double lift_m = 0.0;       // the sole's toe point above the pedal's top (metres)
};

}  // namespace tutti::components
