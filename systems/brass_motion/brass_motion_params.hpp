// SPDX-License-Identifier: MIT
#pragma once
// Timing and shape of valve, slide and embouchure motion (content/brass/motion.json).

#include <string>

#include <tutti/core/result.hpp>

namespace tutti::brass_motion {

struct BrassMotionParams {
  double valve_lead_s = 0.035;          // a valve starts down this long before the onset
  double valve_release_s = 0.035;       // and takes this long to rise
  double valve_hold_rest_s = 0.6;       // a valve stays down over a shorter rest when still needed
  double slide_comfortable_s = 0.15;    // a slide move takes this long when there is time
  double slide_min_move_s = 0.04;       // and never less
  double slide_reach_ramp_s = 1.0;      // the body turns toward a far position over this long
  double slide_reach_bridge_s = 0.6;    // and stays turned between two far ones this close
  double mouth_rest_tension = 0.15;     // embouchure between phrases
  double mouth_low_tension = 0.3;       // at the bottom of the range
  double mouth_tension_exponent = 1.3;  // tension = low + (1 - low) × place^exponent
  double mouth_ramp_s = 0.06;           // the embouchure sets this long before an onset
  double mouth_relax_after_s = 0.5;     // rests longer than this relax the mouth
  double corner_pull_from = 0.45;       // corners start to pull at this tension
};

Result<BrassMotionParams> load_brass_motion_params();  // content/brass/motion.json
Result<BrassMotionParams> load_brass_motion_params(const std::string& file);

}  // namespace tutti::brass_motion
