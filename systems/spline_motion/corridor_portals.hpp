// SPDX-License-Identifier: MIT
#pragma once
// Input validation and the reduction of corridors to "portals".
//
// A corridor [start_s, end_s] x [lo_mm, hi_mm] is a box in the t-x plane. Because the box is
// convex, a straight path between a point of its left edge and a point of its right edge stays
// inside it; so the whole constraint set reduces to vertical segments ("portals") at every
// corridor start and end time. Portals at the same instant (a zero-length corridor, or two
// corridors touching in time) are merged by intersecting their ranges.
//
// Units: seconds and millimetres. Nothing here allocates beyond the returned vector.

#include <cstddef>
#include <span>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/piano_model/hand_corridor.hpp>

namespace tutti::spline_motion {

struct Portal {
  double t_s = 0.0;
  double lo_mm = 0.0;
  double hi_mm = 0.0;
  std::size_t corridor = 0;  // index of the (first) corridor that produced this portal
};

// Checks the contract of piano_model::HandCorridors: every number finite, start_s <= end_s,
// lo_mm <= hi_mm, end_s <= next start_s. The error message names the offending index, e.g.
// "hand corridor 7: lo_mm 412.5 > hi_mm 400".
Status validate_corridors(std::span<const piano_model::HandCorridor> corridors);

// Validates, then returns the portals with strictly increasing t_s (at most 2 per corridor).
// Fails when corridors meeting at one instant have disjoint ranges (the hand would have to
// jump) — the message names both corridors, the time and the ranges.
Result<std::vector<Portal>> corridor_portals(std::span<const piano_model::HandCorridor> corridors);

}  // namespace tutti::spline_motion
