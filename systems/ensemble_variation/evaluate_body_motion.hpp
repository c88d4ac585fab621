#pragma once
// The body motion of one planned performer at time t: a pure, allocation-free function of the
// plan and t (seek anywhere, any order).

#include "components/body_motion.hpp"
#include "ensemble_variation/ensemble_plan.hpp"

namespace tutti::ensemble {

components::BodyMotion evaluate_body_motion(const PerformerMotionPlan& plan, double t_s);

// The parts on their own, for tests and the editor: each in [-1, 1] (or [0, 1]) of its size.
double breath_envelope(const PerformerMotionPlan& plan, double t_s);  // 0..1 x the breath's size
double cue_lift(const CueMotion& cue, double t_s);   // 1 at lift_s, -0.4 at dip_s, 0 outside
double cue_knees(const CueMotion& cue, double t_s);  // 0..1, 1 at dip_s

}  // namespace tutti::ensemble
