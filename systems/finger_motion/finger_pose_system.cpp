// SPDX-License-Identifier: MIT
#include <tutti/finger_motion/finger_pose_system.hpp>

#include <tutti/components/finger.hpp>
#include <tutti/components/hand.hpp>
#include <tutti/finger_motion/evaluate_hand_pose.hpp>

namespace tutti::finger_motion {
namespace {

const PianistMotion* motion_of(const ecs::World& world, ecs::Entity performer) {
  const auto* handle = world.try_get<PianistMotionHandle>(performer);
  return handle != nullptr ? handle->motion.get() : nullptr;
}

}  // namespace

void finger_pose_system(ecs::World& world, const ecs::FrameTime& frame) {
  const double t_s = frame.t_s;
  world.view<components::Hand>().each([&](components::Hand& hand) {
    const PianistMotion* motion = motion_of(world, hand.performer);
    if (motion == nullptr) return;
    const spline_motion::HandState state = spline_motion::evaluate(motion->path(hand.side), t_s);
    hand.x_mm = state.x_mm;
    hand.v_x_mm_per_s = state.v_mm_per_s;
    const HandFingerPlan& plan = motion->fingers.hand(hand.side);
    const double lift = evaluate_pass_over(plan.pass_over, t_s);
    hand.y_mm = motion->fingers.geometry[2].root_y_mm +
                tutti::spline_motion::evaluate_plateau_envelope(plan.reach_in, t_s) +
                lift * plan.pass_over.in_per_lift;
    hand.z_mm = motion->fingers.geometry[2].root_z_mm + lift;
  });
  world.view<components::Finger>().each([&](components::Finger& finger) {
    const components::Hand* hand = world.try_get<components::Hand>(finger.hand);
    if (hand == nullptr) return;
    const PianistMotion* motion = motion_of(world, hand->performer);
    if (motion == nullptr || finger.finger < 1 || finger.finger > 5) return;
    FingerPose pose;
    evaluate_finger_pose(motion->fingers, hand->side, finger.finger, hand->x_mm, t_s, pose);
    finger.side = hand->side;
    finger.spread_rad = pose.spread_rad;
    finger.abduction_rad = pose.abduction_rad;
    finger.mcp_flexion_rad = pose.mcp_flexion_rad;
    finger.pip_flexion_rad = pose.pip_flexion_rad;
    finger.dip_flexion_rad = pose.dip_flexion_rad;
    finger.press_depth = pose.press_depth;
    finger.key = pose.key;
    finger.tip_x_mm = pose.tip_x_mm;
    finger.tip_y_mm = pose.tip_y_mm;
    finger.tip_z_mm = pose.tip_z_mm;
  });
}

void register_finger_motion(ecs::Schedule& schedule) {
  schedule.add(ecs::Phase::evaluate, kFingerMotionSystemName, finger_pose_system,
               ecs::access(ecs::Reads<PianistMotionHandle>{},
                           ecs::Writes<components::Hand, components::Finger>{}));
}

}  // namespace tutti::finger_motion
