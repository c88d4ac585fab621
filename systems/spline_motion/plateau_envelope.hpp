// SPDX-License-Identifier: MIT
#pragma once
// A smooth path that is always at least as high as every span of need, never higher than the
// highest need, and never faster than one ease. Used wherever a body part must be "at least this
// far" for as long as something lasts: the pianist's hand moved in toward the fallboard for the
// black keys a short finger holds (finger_motion), the trombonist's chest turned and slide
// dipped for the slide's far positions (brass_motion).
//
// Planned offline from spans of need. The needs' upper envelope is cut into plateaus (a short dip
// between two is bridged at the lower of them); the path is the highest of the plateaus, each
// eased in by a minimum-jerk ramp that ends where the plateau begins and out by one that starts
// where it ends. Evaluated allocation-free in O(log n) plus the few plateaus within a ramp of t.

#include <vector>

namespace tutti::spline_motion {

struct EnvelopeNeed {
  double from_s = 0.0;  // the need starts
  double to_s = 0.0;    // until; to_s >= from_s
  double value = 0.0;   // how much; <= 0 needs nothing
};

struct PlateauEnvelope {
  // Plateaus, disjoint and in time order: [starts_s[i], ends_s[i]] at values[i] (> 0).
  std::vector<double> starts_s;
  std::vector<double> ends_s;
  std::vector<double> values;
  double ramp_s = 0.15;  // every ease, in and out
};

// `ramp_s` (> 0): the longest ease. A dip shorter than `bridge_s` between two needs is bridged
// at the lower of them: the path does not go down and back up between two close needs.
PlateauEnvelope plan_plateau_envelope(std::vector<EnvelopeNeed> needs, double ramp_s,
                                      double bridge_s);

double evaluate_plateau_envelope(const PlateauEnvelope& path, double t_s) noexcept;

}  // namespace tutti::spline_motion
