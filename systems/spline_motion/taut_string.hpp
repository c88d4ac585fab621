// SPDX-License-Identifier: MIT
#pragma once
// The taut string: the shortest path x(t) through a sequence of hand corridors (Sekiguchi &
// Eiho 1999's "straight as possible" hand path), computed in linear time.
//
// Problem: among all continuous x(t) on [first start_s, last end_s] with lo_i <= x(t) <= hi_i
// while t is inside corridor i (free between corridors; free start and end positions), find
// the one of least length  integral sqrt(1 + x'(t)^2) dt. The answer is unique and piecewise
// linear; it also minimises every strictly convex function of the speed (integral x'^2, peak
// |x'|, ...), which is why it is a good skeleton for a hand's motion.
//
// Properties the smoothing relies on (see README.md):
//  - bends lie only at corridor start/end times, on an edge of the range allowed there;
//  - at a bend on an upper edge the slope increases, on a lower edge it decreases;
//  - the first and last links are horizontal unless they start/end on an edge;
//  - if one position fits every corridor, the string is flat at the middle of the common range.
//
// Cost: O(n) time, O(n) memory, for n corridors (a funnel / string-pulling algorithm).

#include <span>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/piano_model/hand_corridor.hpp>
#include <tutti/spline_motion/corridor_portals.hpp>

namespace tutti::spline_motion {

struct PathPoint {
  double t_s = 0.0;
  double x_mm = 0.0;
};

struct TautString {
  // The string's vertices, strictly increasing in t_s: its two ends and every bend (no three
  // consecutive points are collinear). Empty for no corridors; one point when every corridor
  // collapses to one instant.
  std::vector<PathPoint> points;

  // Linear interpolation of the string; holds the end positions outside [front, back].
  // Precondition: !points.empty(). O(log n).
  double position(double t_s) const;
  // Length in the t-x plane (seconds and millimetres mixed, as in the paper).
  double length() const;
};

// Validates (see corridor_portals) and computes the string.
Result<TautString> taut_string(std::span<const piano_model::HandCorridor> corridors);

// For portals already produced by corridor_portals (strictly increasing t_s, lo <= hi).
TautString taut_string(std::span<const Portal> portals);

// The string's position at every portal time, in one O(n) merge (both are sorted).
std::vector<PathPoint> sample_at_portals(const TautString& string, std::span<const Portal> portals);

}  // namespace tutti::spline_motion
