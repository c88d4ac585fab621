// SPDX-License-Identifier: MIT
#pragma once
// The breaths a wind player takes over the whole piece, as planned (immutable once planned), on
// the performer entity: the editor's timeline draws them, a host reads them as events. Breath is
// the state at the current frame; this is the plan.

#include <vector>

namespace tutti::components {

struct BreathSpan {
  double prepare_s = 0.0;   // the preparatory motion starts (= start_s for most breaths)
  double start_s = 0.0;     // inhaling from start_s ...
  double end_s = 0.0;       // ... to end_s
  double boundary_s = 0.0;  // the onset of the note it precedes (how a scene's marks name it)
  bool marked = false;      // there because of a breath mark
  bool catch_breath = false;
};

struct BreathSchedule {
  std::vector<BreathSpan> breaths;  // in time order
};

}  // namespace tutti::components
