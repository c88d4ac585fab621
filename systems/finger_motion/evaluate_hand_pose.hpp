// SPDX-License-Identifier: MIT
#pragma once
// Evaluation (runtime): the pose of a hand's five fingers at time t from a FingerMotionPlan.
//
// Pure and allocation-free: output goes into a caller-owned struct, the same (plan, path, t) give
// bit-identical poses regardless of what was evaluated before (seek anywhere, any order).
// O(log n) per finger (binary search over its contacts) plus one hand-path evaluation.
//
// What a finger does at t (previous contact p = the last with onset <= t, next n):
//  - holds p's key (press depth 1, tip at the key bottom) until p's offset; then the key rises
//    over release_s (minimum jerk) and the finger relaxes toward its rest line and neutral bend
//    with the relax time constant;
//  - from n's move start it moves laterally from where it was at that moment to n's key with a
//    minimum-jerk profile ending at n's onset (velocity 0 relative to the keys at both ends);
//  - from n's shape start it bends joints 2-3 for a white or black key and goes to hover height
//    above that key, finishing when the stroke starts; joints 2-3 stay fixed during the stroke;
//  - the stroke (joint 1: MCP, thumb: CMC abduction) lowers the tip from hover height to the key
//    bottom, accelerating (quadratic in time), reaching press depth 1 exactly at the onset.
// Joint 1 is solved in closed form for the tip height (finger_chain.hpp); the spread angle is
// atan(d / y) with d the tip's lateral offset from the finger's rest line and y its reach.
// Non-finite t is treated like t before the first contact (NaN) or clamped by the comparisons.

#include <tutti/components/hand_side.hpp>
#include <tutti/finger_motion/finger_motion_plan.hpp>
#include <tutti/finger_motion/hand_pose.hpp>
#include <tutti/spline_motion/hand_path.hpp>

namespace tutti::finger_motion {

// One finger (1..5) of one hand whose reference point is at hand_x_mm at time t_s.
void evaluate_finger_pose(const FingerMotionPlan& plan, components::HandSide side, int finger,
                          double hand_x_mm, double t_s, FingerPose& out) noexcept;

// The hand (path evaluated at t_s) and its five fingers.
void evaluate_hand_pose(const FingerMotionPlan& plan, const spline_motion::HandPath& path,
                        components::HandSide side, double t_s, HandPose& out) noexcept;

}  // namespace tutti::finger_motion
