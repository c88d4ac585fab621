// SPDX-License-Identifier: MIT
#pragma once
// One of a pianist's hands. Written every frame by the finger-motion system (Phase::evaluate)
// from the planned hand path; read by posing (skeleton) and rendering.

#include <tutti/components/hand_side.hpp>
#include <tutti/components/transform.hpp>
#include <tutti/ecs/entity.hpp>

namespace tutti::components {

struct Hand {
  HandSide side = HandSide::right;
  // The pianist entity whose motion plan drives this hand. Entity::null = not driven.
  ecs::Entity performer = ecs::Entity::null;
  // The hand's reference point: the root (MCP knuckle) of the middle finger, keyboard frame.
  double x_mm = 0.0;          // along the keyboard; the hand path's value
  double y_mm = 0.0;          // into the keyboard (knuckle line; negative = in front of the keys)
  double z_mm = 0.0;          // knuckle height above the white keys' top (higher over the other hand)
  double v_x_mm_per_s = 0.0;  // lateral speed along the keyboard
  Rotation rotation;          // of the back of the hand; identity = palm down, fingers toward +y
};

}  // namespace tutti::components
