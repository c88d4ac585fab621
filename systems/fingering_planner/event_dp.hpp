// SPDX-License-Identifier: MIT
#pragma once
// Internal to the planners: the exact planner's dynamic programme over a contiguous range of one
// hand's events, optionally entered from and left to fixed candidates (the unchanged neighbours
// when only part of a plan is re-planned). Deterministic: ties go to the lowest candidate index.

#include <vector>

#include <tutti/fingering_planner/hand_events.hpp>

namespace tutti::fingering_planner {

struct EventRange {
  int first = 0;  // first and last event searched (inclusive)
  int last = -1;
  int entry = -1;  // candidate chosen at event first - 1, or -1 = the range starts the piece
  int exit = -1;   // candidate chosen at event last + 1, or -1 = the range ends the piece
};

// Writes the cheapest candidate per event of `range` into chosen[range.first..range.last]
// (chosen has one entry per event). Transitions of infinite cost count weights.impossible;
// events whose held keys cannot keep their fingers are released and reported in `diagnostics`.
void solve_event_range(const PreparedHand& hand, const FingeringModel& model,
                       const EventRange& range, std::vector<int>& chosen,
                       std::vector<Diagnostic>& diagnostics);

}  // namespace tutti::fingering_planner
