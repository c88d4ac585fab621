// SPDX-License-Identifier: MIT
// evaluate_hand_pose never allocates: this program counts allocations (allocation_counter.hpp) and
// evaluates many frames after planning.
#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include <tutti/finger_motion/evaluate_hand_pose.hpp>
#include "finger_motion_fixture.hpp"

namespace tutti::finger_motion {
namespace {

TEST(EvaluateHandPoseAllocation, NoAllocationPerCall) {
  std::vector<test::TestNote> notes;
  for (int i = 0; i < 64; ++i) {
    notes.push_back({48 + (i * 7) % 24, 0.2 * i, 0.2 * i + 0.3, 1 + i % 5});
  }
  const FingerMotionPlan plan = test::plan_notes(notes, 700, 0);
  const spline_motion::HandPath path = test::constant_path(700);
  HandPose pose;
  const long before = tutti::test::allocation_count();
  double sum = 0;
  for (int i = 0; i < 2000; ++i) {
    evaluate_hand_pose(plan, path, components::HandSide::right, i / 120.0, pose);
    sum += pose.fingers[2].mcp_flexion_rad;
  }
  const long after = tutti::test::allocation_count();
  EXPECT_EQ(after - before, 0);
  EXPECT_TRUE(std::isfinite(sum));
  // The counter works.
  auto* probe = new int(3);
  EXPECT_EQ(tutti::test::allocation_count(), after + 1);
  delete probe;
}

}  // namespace
}  // namespace tutti::finger_motion
