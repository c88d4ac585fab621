// SPDX-License-Identifier: MIT
#pragma once
// A trombone's slide, on the instrument entity, at the current frame. Written every frame by the
// brass pose system (Phase::evaluate); read by posing (the slide node, the player's right arm).

namespace tutti::components {

struct Slide {
  double extension_mm = 0.0;    // from 1st position (closed), along the slide
  double position = 1.0;        // the same as a position number: 1.0 .. 7.0, fractional in moves
  double speed_mm_per_s = 0.0;  // signed, + = moving out
};

}  // namespace tutti::components
