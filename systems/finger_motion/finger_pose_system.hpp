// SPDX-License-Identifier: MIT
#pragma once
// The ECS side of finger motion: a pianist entity carries a handle to its immutable planned
// motion; every frame (Phase::evaluate) finger_pose_system writes each Hand and Finger component
// from it at the frame time.
//
// Wiring: pianist entity: PianistMotionHandle. Hand entity: components::Hand with `performer` =
// the pianist and `side`. Finger entity: components::Finger with `hand` = its hand entity and
// `finger` 1..5. Hands or fingers whose links are stale or lead to no plan are left untouched.

#include <memory>

#include <tutti/ecs/schedule.hpp>
#include <tutti/ecs/world.hpp>
#include <tutti/finger_motion/finger_motion_plan.hpp>
#include <tutti/finger_motion/hand_pose.hpp>
#include <tutti/spline_motion/hand_path.hpp>

namespace tutti::finger_motion {

// Everything needed to pose one pianist's hands; built once after planning, then immutable.
struct PianistMotion {
  FingerMotionPlan fingers;
  spline_motion::HandPath right_path;
  spline_motion::HandPath left_path;

  const spline_motion::HandPath& path(components::HandSide side) const {
    return side == components::HandSide::left ? left_path : right_path;
  }
};

// Component on the pianist entity: a shared handle to immutable plan data (copying the
// component copies the handle, never the plan). Null = not playing.
struct PianistMotionHandle {
  std::shared_ptr<const PianistMotion> motion;
};

// Writes Hand (position, speed) then Finger (angles, press depth, tip) at frame.t_s.
// Allocation-free per frame; reads only plan data and the links above.
void finger_pose_system(ecs::World& world, const ecs::FrameTime& frame);

inline constexpr const char* kFingerMotionSystemName = "finger_motion";

// Adds finger_pose_system to Phase::evaluate under kFingerMotionSystemName.
void register_finger_motion(ecs::Schedule& schedule);

}  // namespace tutti::finger_motion
