#pragma once
// Closed-form geometry of one finger, header-only and allocation-free (used by evaluate).
//
// A finger is a planar chain of three segments in the vertical plane through the finger. Joint 1
// (the stroke joint: MCP, or the thumb's CMC abduction) turns the whole chain; joints 2 and 3 are
// the "bend" (PIP and DIP; thumb MCP and IP), joint 3 = coupling x joint 2. With the bend fixed,
// the part of the chain past joint 1 is a rigid vector (a forward, b down) of length R at angle
// alpha below the first segment, so the tip drop below the root is R sin(j1 + alpha): the stroke
// angle for a wanted drop is asin(drop / R) - alpha and the horizontal reach is
// sqrt(R^2 - drop^2). Millimetres and radians; flexion > 0 bends toward the palm.

#include <algorithm>
#include <cmath>

#include "finger_motion/finger_motion_params.hpp"

namespace tutti::finger_motion {

// The minimum-jerk profile 10u^3 - 15u^4 + 6u^5 on u clamped to [0, 1]: 0 -> 1 with zero
// velocity and acceleration at both ends.
inline double min_jerk(double u) noexcept {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

// a + (b - a) u, returning b exactly when u >= 1 (so "arrived" is bit-exact).
inline double blend(double a, double b, double u) noexcept {
  return u >= 1.0 ? b : a + (b - a) * u;
}

// The rigid part of a chain past joint 1 for a given bend (joint 2 angle).
struct ChainShape {
  double bend_rad = 0.0;    // joint 2
  double joint3_rad = 0.0;  // coupling x joint 2
  double reach_mm = 0.0;    // R, root to tip with joint 1 = 0
  double alpha_rad = 0.0;   // angle of the root->tip line below the first segment
};

inline ChainShape chain_shape(const FingerGeometry& g, double bend_rad) noexcept {
  const double j3 = g.coupling * bend_rad;
  const double a = g.phalanges_mm[0] + g.phalanges_mm[1] * std::cos(bend_rad) +
                   g.phalanges_mm[2] * std::cos(bend_rad + j3);
  const double b =
      g.phalanges_mm[1] * std::sin(bend_rad) + g.phalanges_mm[2] * std::sin(bend_rad + j3);
  return {bend_rad, j3, std::hypot(a, b), std::atan2(b, a)};
}

struct StrokeSolution {
  double joint1_rad = 0.0;  // stroke joint angle
  double reach_y_mm = 0.0;  // horizontal root->tip distance (into the keys), >= 0
};

// Joint 1 so that the tip is `drop_mm` below the root; a drop beyond reach is clamped to +-R.
inline StrokeSolution solve_stroke(const ChainShape& shape, double drop_mm) noexcept {
  const double r = shape.reach_mm;
  const double d = std::clamp(drop_mm, -r, r);
  return {std::asin(d / r) - shape.alpha_rad, std::sqrt(std::max(r * r - d * d, 0.0))};
}

// The spread angle: the direction of the horizontal root->tip line, atan(d / y), where d is the
// tip's lateral offset (keyboard x) from the finger's rest line and y its reach into the keys.
// `mirror` = +1 for the right hand, -1 for the left, so > 0 always means toward the little finger.
inline double spread_angle_rad(double d_mm, double reach_y_mm, double mirror) noexcept {
  return std::atan(mirror * d_mm / std::max(reach_y_mm, 1.0));
}

}  // namespace tutti::finger_motion
