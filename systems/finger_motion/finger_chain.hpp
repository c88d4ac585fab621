// SPDX-License-Identifier: MIT
#pragma once
// Closed-form geometry of one finger, header-only and allocation-free (used by evaluate).
//
// A finger is a planar chain of three segments in the vertical plane through the finger. Joint 1
// (the stroke joint: MCP, or the thumb's CMC abduction) turns the whole chain; joints 2 and 3 are
// the "bend" (PIP and DIP; thumb MCP and IP), joint 3 = coupling x joint 2. With the bend fixed,
// the part of the chain past joint 1 is a rigid vector (a forward, b down) of length R at angle
// alpha below the first segment, so the tip drop below the root is R sin(j1 + alpha): the stroke
// angle for a wanted drop d is asin(d / R) - alpha and the horizontal reach is
// y = sqrt(R^2 - d^2). solve_stroke evaluates that difference of angles as the angle of
// (y a + d b, d a - y b), the cosine and sine of asin(d/R) - alpha times R^2: one atan of their
// ratio (atan2 beyond +-90 degrees), so a shape needs only (a, b) and a call no hypot, asin or
// second atan2. Millimetres and radians; flexion > 0 bends toward the palm.

#include <algorithm>
#include <cmath>

#include <tutti/finger_motion/finger_motion_params.hpp>

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

// The rigid part of a chain past joint 1 for a given bend (joint 2 angle): the root->tip vector
// with joint 1 = 0, along the first segment (a) and perpendicular to it, toward the palm (b).
// R = hypot(a, b) and alpha = atan2(b, a) in the terms above.
struct ChainShape {
  double bend_rad = 0.0;    // joint 2
  double joint3_rad = 0.0;  // coupling x joint 2
  double forward_mm = 0.0;  // a
  double down_mm = 0.0;     // b
};

inline ChainShape chain_shape(const FingerGeometry& g, double bend_rad) noexcept {
  const double j3 = g.coupling * bend_rad;
  const double a = g.phalanges_mm[0] + g.phalanges_mm[1] * std::cos(bend_rad) +
                   g.phalanges_mm[2] * std::cos(bend_rad + j3);
  const double b =
      g.phalanges_mm[1] * std::sin(bend_rad) + g.phalanges_mm[2] * std::sin(bend_rad + j3);
  return {bend_rad, j3, a, b};
}

struct StrokeSolution {
  double joint1_rad = 0.0;  // stroke joint angle
  double reach_y_mm = 0.0;  // horizontal root->tip distance (into the keys), >= 0
};

// Joint 1 so that the tip is `drop_mm` below the root; a drop beyond reach is clamped to +-R.
// joint1 = asin(d / R) - alpha, in (-pi, pi] (a physical chain has |asin(d/R) - alpha| < pi).
inline StrokeSolution solve_stroke(const ChainShape& shape, double drop_mm) noexcept {
  const double a = shape.forward_mm;
  const double b = shape.down_mm;
  const double r2 = a * a + b * b;
  if (drop_mm * drop_mm >= r2) {  // fully stretched up or down: y = 0, joint1 = +-pi/2 - alpha
    const double d = std::copysign(std::sqrt(r2), drop_mm);
    return {std::atan2(d * a, d * b), 0.0};
  }
  const double y = std::sqrt(r2 - drop_mm * drop_mm);
  const double sine = drop_mm * a - y * b;    // sin(joint1) x R^2
  const double cosine = y * a + drop_mm * b;  // cos(joint1) x R^2
  // |joint1| < pi/2 (every stroke in practice): atan of the ratio, much cheaper than atan2.
  return {cosine > 0.0 ? std::atan(sine / cosine) : std::atan2(sine, cosine), y};
}

// A finger reaching further down than its bend spans (from a hand lifted over the other one,
// pass_over.hpp) straightens until it spans the drop with a little give: the most bent shape
// that does, found by bisection. `planned`: the shape it would have.
inline ChainShape reaching_shape(const FingerGeometry& g, const ChainShape& planned,
                                 double drop_mm) noexcept {
  constexpr double kGive = 0.95;
  const auto spans = [drop_mm](const ChainShape& s) {
    return drop_mm <= kGive * std::hypot(s.forward_mm, s.down_mm);
  };
  if (spans(planned)) return planned;
  double straight = 0.0;
  double bent = planned.bend_rad;
  for (int round = 0; round < 12; ++round) {
    const double mid = 0.5 * (straight + bent);
    if (spans(chain_shape(g, mid))) {
      straight = mid;
    } else {
      bent = mid;
    }
  }
  return chain_shape(g, straight);
}

// The shape whose stroke over `drop_mm` reaches `reach_y_mm` into the keys: a finger holding its
// key while the hand moves in or out flexes or straightens to keep its pad where it landed.
// Bisection over the bend between straight and `most_bend_rad` (a bend flexes the tip back toward
// the palm: the reach falls as the bend grows); a reach out of that range gets the nearest end.
inline ChainShape shape_reaching_y(const FingerGeometry& g, double drop_mm, double reach_y_mm,
                                   double most_bend_rad) noexcept {
  double straight = 0.0;
  double bent = most_bend_rad;
  for (int round = 0; round < 16; ++round) {
    const double mid = 0.5 * (straight + bent);
    if (solve_stroke(chain_shape(g, mid), drop_mm).reach_y_mm > reach_y_mm) {
      straight = mid;
    } else {
      bent = mid;
    }
  }
  return chain_shape(g, 0.5 * (straight + bent));
}

// The spread angle: the direction of the horizontal root->tip line, atan(d / y), where d is the
// tip's lateral offset (keyboard x) from the finger's rest line and y its reach into the keys.
// `mirror` = +1 for the right hand, -1 for the left, so > 0 always means toward the little finger.
inline double spread_angle_rad(double d_mm, double reach_y_mm, double mirror) noexcept {
  return std::atan(mirror * d_mm / std::max(reach_y_mm, 1.0));
}

}  // namespace tutti::finger_motion
