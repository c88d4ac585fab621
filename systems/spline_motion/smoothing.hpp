// SPDX-License-Identifier: MIT
#pragma once
// Planning: corridors -> taut string -> smooth HandPath.
//
// Default (SmoothingMode::monotone_quintic): knots are the taut string's positions at EVERY
// corridor start and end time; knot slopes are the Fritsch-Butland weighted harmonic mean of
// the neighbouring secants, zero where the secants change sign or vanish and at both ends,
// capped at 2x the smaller secant; knot accelerations are zero; each piece is the quintic
// Hermite interpolant of that data. Result: C2, at rest at both ends.
//
// Why it never leaves a corridor (the full argument is in README.md):
//  1. while corridor i is held, t runs over exactly one piece [start_i, end_i] (its start and
//     end are consecutive knots), and both knot values are taut-string positions inside
//     [lo_i, hi_i];
//  2. a quintic Hermite piece with zero end accelerations and end slopes of the secant's sign
//     and at most 2x its size is monotone (its derivative is >= 0.125 x secant at worst), so
//     the piece stays between its two knot values, hence inside [lo_i, hi_i]. QED.
// Between corridors the hand is free; there the piece is still monotone (no overshoot).
//
// Cost: O(n) time and memory for n corridors.

#include <span>

#include <tutti/core/result.hpp>
#include <tutti/piano_model/hand_corridor.hpp>
#include <tutti/spline_motion/corridor_portals.hpp>
#include <tutti/spline_motion/hand_path.hpp>
#include <tutti/spline_motion/taut_string.hpp>

namespace tutti::spline_motion {

struct PlanOptions {
  SmoothingMode smoothing = SmoothingMode::monotone_quintic;
};

// Validates the corridors (errors name the index), computes the taut string and smooths it.
// No corridors -> an empty path (evaluates to 0 mm, at rest).
Result<HandPath> plan_hand_path(std::span<const piano_model::HandCorridor> corridors,
                                const PlanOptions& options = {});

// The smoothing step alone. `portals` must be those the string was computed from.
// Fails only when knots are so close in time that a piece's coefficients overflow.
Result<HandPath> smooth_taut_string(const TautString& string, std::span<const Portal> portals,
                                    SmoothingMode mode);

}  // namespace tutti::spline_motion
