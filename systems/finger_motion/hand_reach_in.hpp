#pragma once
// How far a hand sits in toward the fallboard, beyond its rest line, over time. A short finger
// (the little finger, the thumb) cannot reach a black key from where it strikes the white keys:
// the black keys begin about 55 mm behind the white keys' front edge. Pianists move the whole
// hand in while such a key is struck and held, and back out when it is let go; this is that move.
//
// Planned offline from spans of need (one per key contact: how far in the hand must be while the
// contact lasts). The needs' upper envelope is cut into plateaus (a short dip between two is
// bridged at the lower of them); the path is the highest of the plateaus, each eased in by a
// minimum-jerk ramp that ends where the plateau begins and out by one that starts where it ends.
// So the hand is always at least as far in as a held key needs, never further than the deepest
// need, and never faster than one ramp moves it, however close the needs' edges lie. Evaluated
// allocation-free in O(log n) plus the few plateaus within a ramp of t.

#include <vector>

namespace tutti::finger_motion {

struct ReachInNeed {
  double from_s = 0.0;  // the contact starts to need it (its shaping before the stroke)
  double to_s = 0.0;    // until (its release is over); to_s >= from_s
  double in_mm = 0.0;   // how far in; <= 0 needs nothing
};

struct HandReachIn {
  // Plateaus, disjoint and in time order: [starts_s[i], ends_s[i]] at values_mm[i] (> 0).
  std::vector<double> starts_s;
  std::vector<double> ends_s;
  std::vector<double> values_mm;
  double ramp_s = 0.15;  // every ease, in and out
};

// `ramp_s` (> 0): the longest ease. A dip shorter than `bridge_s` between two needs is bridged
// at the lower of them: the hand does not go out and back in between two close black keys.
HandReachIn plan_reach_in(std::vector<ReachInNeed> needs, double ramp_s, double bridge_s);

double evaluate_reach_in(const HandReachIn& path, double t_s) noexcept;

}  // namespace tutti::finger_motion
