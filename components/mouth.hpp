// SPDX-License-Identifier: MIT
#pragma once
// A brass player's embouchure at the current frame, on the performer entity; drives the face's
// morph targets. Written every frame by the brass pose system (Phase::evaluate).

namespace tutti::components {

struct Mouth {
  double tension = 0.0;      // 0 = relaxed .. 1 = the top of the instrument's range
  double corner_pull = 0.0;  // 0 .. 1, corners drawn in / firmed (rises with the register)
  double open = 0.0;         // 0 = closed on the mouthpiece .. 1 = open for a full breath
  bool buzzing = false;      // a note is sounding
};

}  // namespace tutti::components
