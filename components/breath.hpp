// SPDX-License-Identifier: MIT
#pragma once
// A wind player's breathing at the current frame, on the performer entity. Written every frame by
// the brass pose system from the breath plan (Phase::evaluate); read by ensemble-variation (the
// breathing body motion) and the face (strain).

namespace tutti::components {

struct Breath {
  double air = 1.0;        // 0 = empty lungs .. 1 = full
  double inhale = 0.0;     // 0 .. 1: how far into a breath (mouth opens, shoulders rise)
  double preparing = 0.0;  // 0 .. 1: the preparatory motion before a breath after a long rest
  double strain = 0.0;     // 0 .. 1: the phrase outlasts the air
  int breath_index = -1;   // the breath event under way or last taken, -1 = none yet
};

}  // namespace tutti::components
