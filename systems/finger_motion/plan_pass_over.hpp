// SPDX-License-Identifier: MIT
#pragma once
// Planning (offline, allocates) of where each hand passes over the other (pass_over.hpp).

#include <tutti/finger_motion/finger_motion_plan.hpp>
#include <tutti/finger_motion/pass_over.hpp>
#include <tutti/spline_motion/hand_path.hpp>

namespace tutti::finger_motion {

// Fills plan.right.pass_over and plan.left.pass_over from the paths and the contacts, which must
// be scheduled already (stroke starts and release ends known).
void plan_pass_over(FingerMotionPlan& plan, const spline_motion::HandPath& right_path,
                    const spline_motion::HandPath& left_path, const PassOverParams& params);

}  // namespace tutti::finger_motion
