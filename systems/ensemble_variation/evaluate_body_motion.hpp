// SPDX-License-Identifier: MIT
#pragma once
// The body motion of one planned performer at time t: a pure, allocation-free function of the
// plan and t (seek anywhere, any order).

#include <tutti/components/body_motion.hpp>
#include <tutti/ensemble_variation/ensemble_plan.hpp>

namespace tutti::ensemble_variation {

// `breath_strain` is the air model's strain at t (components::Breath::strain, 0 without one);
// BodyMotion::strain is it as the player's expression shapes it.
components::BodyMotion evaluate_body_motion(const PerformerMotionPlan& plan, double t_s,
                                            double breath_strain = 0.0);

// The parts on their own, for tests and the editor: each in [-1, 1] (or [0, 1]) of its size.
double breath_envelope(const PerformerMotionPlan& plan, double t_s);  // 0..1 x the breath's size
double cue_lift(const CueMotion& cue, double t_s);   // 1 at lift_s, -0.4 at dip_s, 0 outside
double cue_knees(const CueMotion& cue, double t_s);  // 0..1, 1 at dip_s
// The cue under way at t (the last one started at or before t), nullptr before the first.
const CueMotion* cue_at(const PerformerMotionPlan& plan, double t_s);

// How much of each expression shows at t: amount x a ramp in / out at the span's edges, 0..1.
struct ExpressionLevel {
  double strain = 0.0;
  double relaxed = 0.0;
};
ExpressionLevel expression_at(const PerformerMotionPlan& plan, double t_s);

}  // namespace tutti::ensemble_variation
