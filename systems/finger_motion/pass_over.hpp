// SPDX-License-Identifier: MIT
#pragma once
// One hand passing over the other. Where the hands' paths bring them onto each other (a leap to
// the far side of the other hand, as in a Polonaise's right hand diving to the bass past the
// left's held chord, or a note held there), a pianist has the crossing hand over the other one,
// never through it.
//
// Planned offline (plan_pass_over.hpp) from both hands' paths: wherever their reference points
// come closer than `gap_mm` on their own sides or lie crossed by less than `crossed_mm`
// (PassOverParams, finger_motion_params.hpp), the hand that travels further over that time is
// lifted by `lift_mm`, easing up over `ease_s` before and down over `ease_s` after by minimum
// jerk. The whole hand rises; a finger pressing a key meanwhile reaches down from it,
// straightened as far as it must be (finger_chain.hpp, reaching_shape), and the hand moves in
// toward the fallboard by the reach that costs. Evaluated allocation-free in O(log n).

#include <vector>

namespace tutti::finger_motion {

// A hand lifted over [top_from_s, top_to_s], easing up from rise_from_s and down by down_to_s.
struct PassOverLift {
  double rise_from_s = 0.0;
  double top_from_s = 0.0;
  double top_to_s = 0.0;
  double down_to_s = 0.0;
  double height_mm = 0.0;
};

// Lifts in time order, disjoint.
struct PassOver {
  std::vector<PassOverLift> lifts;
  // A lifted hand's pressing fingers straighten to reach down, so their pads land nearer the
  // hand: the hand moves in toward the fallboard by this much per mm of lift (the middle
  // finger's lost reach on a white key), and its pads land where they would have.
  double in_per_lift = 0.0;
};

// How high the hand is lifted at t (mm, >= 0).
double evaluate_pass_over(const PassOver& pass_over, double t_s) noexcept;

}  // namespace tutti::finger_motion
