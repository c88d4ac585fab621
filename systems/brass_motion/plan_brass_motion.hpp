// SPDX-License-Identifier: MIT
#pragma once
// From a fingered line (brass fingering planner) to the motion of valves, slide and embouchure.
//
// Valves: a valve starts down valve_lead_s before the onset of a note that needs it (less when the
// notes are faster) and is fully down at the onset; it stays down while the following notes need
// it (also over rests shorter than valve_hold_rest_s) and rises in the change window before the
// first note that does not, or after the last note when a rest follows.
// Slide: moves inside the change window before each onset (brass_line.hpp), arriving at the onset,
// taking slide_comfortable_s when there is time and never faster than the instrument's top speed;
// a move that cannot fit arrives late (counted in late_slide_moves).
// Mouth: tension from the written pitch's place in the instrument's range, set mouth_ramp_s before
// each onset, relaxed to mouth_rest_tension over rests longer than mouth_relax_after_s.

#include <tutti/brass_model/brass_line.hpp>
#include <tutti/brass_motion/brass_motion_params.hpp>
#include <tutti/brass_motion/brass_motion_plan.hpp>

namespace tutti::brass_motion {

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::ChangeWindow;
using brass_model::Instrument;

// The line must have its instrument and its fingerings (LineNote::fingering); notes without one
// are not played. `window` must be the one the fingering planner used.
BrassMotionPlan plan_brass_motion(const BrassLine& line, const BrassMotionParams& params,
                                  const ChangeWindow& window);

// Tension (0..1) of a written pitch on `instrument` under `params`.
double embouchure_tension(const Instrument& instrument, int written,
                          const BrassMotionParams& params);

}  // namespace tutti::brass_motion
