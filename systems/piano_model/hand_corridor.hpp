// SPDX-License-Identifier: MIT
#pragma once
// Where one hand's reference point (the resting middle finger) may be while keys are held: the
// fingering planner produces a sequence of corridors, spline-motion threads the hand's path
// through them. Between two corridors the hand moves freely.

#include <vector>

namespace tutti::piano_model {

struct HandCorridor {
  double start_s = 0.0;  // first key of this event goes down
  double end_s = 0.0;    // the event's keys are released (or the next event starts)
  double lo_mm = 0.0;    // allowed hand positions, keyboard x in millimetres
  double hi_mm = 0.0;    // lo_mm <= hi_mm
  // The event's lowest and highest keys, held ones included (keyboard x in millimetres), when
  // the planner knows them: where the hand's outer fingers are, however far it stretches.
  bool keys_known = false;
  double keys_lo_mm = 0.0;
  double keys_hi_mm = 0.0;
};

// Sorted by start_s; consecutive corridors do not overlap in time (end_s <= next start_s).
using HandCorridors = std::vector<HandCorridor>;

}  // namespace tutti::piano_model
