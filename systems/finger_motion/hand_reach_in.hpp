#pragma once
// How far a hand sits in toward the fallboard, beyond its rest line, over time. A short finger
// (the little finger, the thumb) cannot reach a black key from where it strikes the white keys:
// the black keys begin about 55 mm behind the white keys' front edge. Pianists move the whole
// hand in while such a key is struck and held, and back out when it is let go; this is that move.
//
// Planned offline from spans of need (one per key contact: how far in the hand must be while the
// contact lasts); evaluated allocation-free in O(log n). The path is the upper envelope of the
// needs, each change eased by a minimum-jerk ramp that rises before the span that needs more and
// falls after the span that needed it: the hand is always at least as far in as a held key needs.

#include <vector>

namespace tutti::finger_motion {

struct ReachInNeed {
  double from_s = 0.0;  // the contact starts to need it (its shaping before the stroke)
  double to_s = 0.0;    // until (its release is over); to_s >= from_s
  double in_mm = 0.0;   // how far in; <= 0 needs nothing
};

struct HandReachIn {
  // Step boundaries, strictly increasing; after boundary i the envelope is values_mm[i] (before
  // the first it is 0). ramp_s[i] is the ease at boundary i: before it when the value rises,
  // after it when it falls, never more than half of either neighbouring step.
  std::vector<double> times_s;
  std::vector<double> values_mm;
  std::vector<double> ramp_s;
};

// `ramp_s` (> 0): the longest ease. A dip shorter than `bridge_s` between two needs is bridged
// at the lower of them: the hand does not go out and back in between two close black keys.
HandReachIn plan_reach_in(std::vector<ReachInNeed> needs, double ramp_s, double bridge_s);

double evaluate_reach_in(const HandReachIn& path, double t_s) noexcept;

}  // namespace tutti::finger_motion
