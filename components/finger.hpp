// SPDX-License-Identifier: MIT
#pragma once
// One finger of one hand: the joint angles that pose it and where its tip is. Written every frame
// by the finger-motion system (Phase::evaluate), read by posing and rendering.
//
// Angles are radians. Flexion > 0 bends toward the palm (the tip goes down). For fingers 2..5 the
// chain is MCP (knuckle) -> PIP -> DIP; for the thumb (finger 1) the stroke joint is the CMC
// abduction (`abduction_rad`), then `mcp_flexion_rad` (thumb MCP) and `pip_flexion_rad` (thumb IP);
// its `dip_flexion_rad` stays 0.

#include <tutti/components/hand_side.hpp>
#include <tutti/ecs/entity.hpp>

namespace tutti::components {

struct Finger {
  ecs::Entity hand = ecs::Entity::null;  // the Hand entity this finger belongs to
  HandSide side = HandSide::right;  // copy of the hand's side, for systems that only see fingers
  int finger = 1;                   // 1 = thumb .. 5 = little finger

  // Lateral angle of the horizontal root->tip line from straight ahead (+y), about the vertical
  // axis. > 0 = toward the little-finger side (+x for the right hand, -x for the left).
  double spread_rad = 0.0;
  double abduction_rad = 0.0;    // thumb only: the CMC stroke angle (0 for fingers 2..5)
  double mcp_flexion_rad = 0.0;  // knuckle joint (the stroke joint of fingers 2..5)
  double pip_flexion_rad = 0.0;  // middle joint (thumb: IP joint)
  double dip_flexion_rad = 0.0;  // last joint, coupled to PIP (~2/3 of it); thumb: 0

  double press_depth = 0.0;  // how far the finger holds its key down: 0 = up .. 1 = key bottom
  int key = -1;              // MIDI key the finger is pressing (press_depth > 0), else -1

  // Fingertip in the keyboard frame (see transform.hpp), millimetres.
  double tip_x_mm = 0.0;
  double tip_y_mm = 0.0;
  double tip_z_mm = 0.0;
};

}  // namespace tutti::components
