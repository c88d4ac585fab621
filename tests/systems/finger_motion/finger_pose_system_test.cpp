// SPDX-License-Identifier: MIT
// A tiny world: one pianist, one right hand, five fingers; one frame of the schedule.
#include <tutti/finger_motion/finger_pose_system.hpp>

#include <gtest/gtest.h>

#include <memory>

#include <tutti/components/finger.hpp>
#include <tutti/components/hand.hpp>
#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include "finger_motion_fixture.hpp"

namespace tutti::finger_motion {
namespace {

TEST(FingerPoseSystem, WritesHandAndFingersFromThePianistsPlan) {
  const Models& m = test::models();
  const double x = m.keyboard.x_mm(60);
  auto motion = std::make_shared<PianistMotion>();
  motion->fingers = test::plan_notes({{60, 1.0, 1.5, 3}, {64, 1.0, 1.5, 5}}, x, 0);
  motion->right_path = test::constant_path(x);

  ecs::World world;
  const ecs::Entity pianist = world.create();
  world.add<PianistMotionHandle>(pianist, std::shared_ptr<const PianistMotion>(motion));
  const ecs::Entity hand = world.create();
  components::Hand hand_value;
  hand_value.performer = pianist;
  world.add<components::Hand>(hand, hand_value);
  ecs::Entity fingers[5];
  for (int f = 1; f <= 5; ++f) {
    fingers[f - 1] = world.create();
    components::Finger finger;
    finger.hand = hand;
    finger.finger = f;
    world.add<components::Finger>(fingers[f - 1], finger);
  }
  // A finger whose hand is gone is left alone.
  const ecs::Entity orphan = world.create();
  components::Finger orphan_value;
  orphan_value.hand = world.create();
  world.destroy(orphan_value.hand);
  orphan_value.press_depth = 0.25;
  world.add<components::Finger>(orphan, orphan_value);

  ecs::Schedule schedule;
  register_finger_motion(schedule);
  EXPECT_EQ(schedule.describe(), "evaluate: finger_motion\n");
  schedule.run(world, {1.0, 1.0 / 60});

  EXPECT_EQ(world.get<components::Hand>(hand).x_mm, x);
  const auto& middle = world.get<components::Finger>(fingers[2]);
  EXPECT_EQ(middle.press_depth, 1.0);
  EXPECT_EQ(middle.tip_x_mm, x);
  EXPECT_EQ(middle.spread_rad, 0.0);
  EXPECT_GT(middle.mcp_flexion_rad, 0.0);
  const auto& little = world.get<components::Finger>(fingers[4]);
  EXPECT_EQ(little.press_depth, 1.0);
  EXPECT_EQ(little.tip_x_mm, m.keyboard.x_mm(64));
  EXPECT_EQ(little.key, 64);  // which key to press down on the piano model
  EXPECT_EQ(world.get<components::Finger>(fingers[1]).press_depth, 0.0);
  EXPECT_EQ(world.get<components::Finger>(fingers[1]).key, -1);
  EXPECT_EQ(world.get<components::Finger>(orphan).press_depth, 0.25);

  // The same as evaluating the plan directly.
  HandPose pose;
  evaluate_hand_pose(motion->fingers, motion->right_path, components::HandSide::right, 1.0, pose);
  EXPECT_EQ(middle.mcp_flexion_rad, pose.fingers[2].mcp_flexion_rad);
  EXPECT_EQ(little.spread_rad, pose.fingers[4].spread_rad);

  // Later frame: released.
  schedule.run(world, {3.0, 1.0 / 60});
  EXPECT_EQ(world.get<components::Finger>(fingers[2]).press_depth, 0.0);
  EXPECT_EQ(world.get<components::Finger>(fingers[2]).key, -1);
}

}  // namespace
}  // namespace tutti::finger_motion
