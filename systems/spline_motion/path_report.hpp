// SPDX-License-Identifier: MIT
#pragma once
// Checking a planned path against corridors: how often and how far it leaves them, and how
// fast it moves. Offline (for tests, tools and logs); O(n log n) for n corridors.

#include <cstddef>
#include <span>

#include <tutti/piano_model/hand_corridor.hpp>
#include <tutti/spline_motion/hand_path.hpp>

namespace tutti::spline_motion {

struct ReportOptions {
  int samples_per_corridor = 32;  // evaluate() at this many evenly spaced times per corridor
  double tolerance_mm = 1e-9;     // distances up to this are not violations
};

struct PathReport {
  std::size_t violating_corridors = 0;  // corridors the path leaves at some time while held
  double worst_violation_mm = 0.0;      // largest distance outside a corridor
  std::size_t worst_corridor = 0;       // where it happens (meaningful if violating_corridors)
  double worst_t_s = 0.0;  // a sample time, or the start of the piece holding an analytic extremum
  // Over all pieces (inside pieces; the velocity jumps of SmoothingMode::none are not counted).
  double peak_speed_mm_per_s = 0.0;
  double peak_acceleration_mm_per_s2 = 0.0;
};

// For each corridor: the path's minimum and maximum over [start_s, end_s], both from dense
// samples through evaluate() and from every piece overlapping the corridor (its ends and the
// roots of its derivative, i.e. its true extrema up to root bracketing on 16 steps per piece).
// The corridors need not be the ones the path was planned from.
PathReport corridor_violations(const HandPath& path,
                               std::span<const piano_model::HandCorridor> corridors,
                               const ReportOptions& options = {});

}  // namespace tutti::spline_motion
