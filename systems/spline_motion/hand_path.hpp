// SPDX-License-Identifier: MIT
#pragma once
// The planned hand path: a piecewise polynomial x(t) (millimetres over seconds) and its pure,
// allocation-free evaluation.
//
// Ownership: a HandPath owns its knots and pieces; it is a value (copyable, movable) and is
// immutable once built by plan_hand_path (smoothing.hpp). Thread-safe for concurrent evaluate().

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <tutti/spline_motion/polynomial.hpp>

namespace tutti::spline_motion {

enum class SmoothingMode {
  // DEFAULT. C2 piecewise quintic through the taut string at every corridor start/end, each
  // piece monotone between its knots: provably never leaves a corridor, never overshoots.
  monotone_quintic,
  // C1 monotone cubic (Fritsch-Carlson / PCHIP) through the same knots: also provably inside.
  pchip,
  // The paper's choice: C2 natural cubic spline through the taut string's bends only. Smooth
  // but may overshoot (and leave a corridor) when bends are close.
  natural_spline,
  // The taut string itself (C0: velocity jumps at bends).
  none,
};

// "monotone_quintic", "pchip", "natural_spline", "none"; "?" for a value outside the enum.
const char* to_string(SmoothingMode mode);
// The inverse of to_string (exact names only); nullopt for anything else.
std::optional<SmoothingMode> smoothing_mode_from_string(std::string_view name) noexcept;

struct HandState {
  double x_mm = 0.0;
  double v_mm_per_s = 0.0;
  double a_mm_per_s2 = 0.0;
};

class HandPath {
 public:
  HandPath() = default;  // empty: evaluates to x = 0, at rest

  // Pieces: pieces[k] is valid on [knot_times[k], knot_times[k+1]] in dt = t - knot_times[k].
  // Preconditions (the planner guarantees them): knot_times strictly increasing and finite;
  // pieces.size() + 1 == knot_times.size() (or both empty); `end_x_mm` is the value at the last
  // knot. `monotone` promises each piece is monotone between its knot values; evaluate() then
  // clamps to them, so rounding can never push a position past a knot value.
  HandPath(SmoothingMode mode, std::vector<double> knot_times, std::vector<Poly5> pieces,
           double end_x_mm, bool monotone);

  bool empty() const { return knot_times_.empty(); }
  SmoothingMode mode() const { return mode_; }
  bool monotone_pieces() const { return monotone_; }
  std::span<const double> knot_times() const { return knot_times_; }
  std::span<const Poly5> pieces() const { return pieces_; }
  double start_s() const { return empty() ? 0.0 : knot_times_.front(); }
  double end_s() const { return empty() ? 0.0 : knot_times_.back(); }
  double start_x_mm() const;
  double end_x_mm() const { return end_x_mm_; }

 private:
  SmoothingMode mode_ = SmoothingMode::monotone_quintic;
  std::vector<double> knot_times_;
  std::vector<Poly5> pieces_;
  double end_x_mm_ = 0.0;
  bool monotone_ = true;
};

// Position, velocity and acceleration at t_s. Pure (same t -> bit-identical result), no
// allocation, O(log n) (binary search over knots). Before the first knot the hand holds its
// start position, after the last it holds its end position (velocity and acceleration 0).
// Non-finite t_s is treated as "before the start" (NaN) or clamped (+-inf).
HandState evaluate(const HandPath& path, double t_s) noexcept;

}  // namespace tutti::spline_motion
