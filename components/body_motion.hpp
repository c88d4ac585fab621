// SPDX-License-Identifier: MIT
#pragma once
// How a performer's body moves away from the instrument's stock pose at the current frame, on the
// performer entity: sway, weight shifts, the breathing body, the lead's cues, the editor's
// expressions. Written every frame by systems/ensemble_variation (Phase::express); the stage
// turns it into joint rotations.
// Directions are the player's own: + sideways = their left, + lean = back, + nod = forward.

namespace tutti::components {

struct BodyMotion {
  float hips_shift_m = 0.0f;     // weight on the left foot (+) or the right (-)
  float knee_flex_m = 0.0f;      // how far the hips sink as the knees bend (>= 0)
  float sway_rad = 0.0f;         // the upper body leans to the player's left (+) about the hips
  float twist_rad = 0.0f;        // the upper body turns to the player's left (+)
  float lean_back_rad = 0.0f;    // the chest leans back (+), breathing in
  float shoulder_lift_m = 0.0f;  // the chest and shoulders rise (+), breathing in
  float head_nod_rad = 0.0f;     // the head tips forward (+)
  float bell_lift_rad = 0.0f;    // the instrument's bell rises (+): the cue
  // 0 .. 1: the strain the face shows, Breath::strain as the player's expression (strain /
  // relaxed spans) shapes it; a double like Breath::strain, so without an expression the face
  // shows exactly the air model's strain.
  double strain = 0.0;
};

}  // namespace tutti::components
