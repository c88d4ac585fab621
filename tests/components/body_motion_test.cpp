// SPDX-License-Identifier: MIT
// components/body_motion.hpp compiles on its own; a default BodyMotion is the stock pose.
#include <tutti/components/body_motion.hpp>

#include <gtest/gtest.h>

TEST(BodyMotionComponent, DefaultsToTheStockPose) {
  const tutti::components::BodyMotion m;
  EXPECT_EQ(m.hips_shift_m, 0.0f);
  EXPECT_EQ(m.knee_flex_m, 0.0f);
  EXPECT_EQ(m.sway_rad, 0.0f);
  EXPECT_EQ(m.twist_rad, 0.0f);
  EXPECT_EQ(m.lean_back_rad, 0.0f);
  EXPECT_EQ(m.shoulder_lift_m, 0.0f);
  EXPECT_EQ(m.head_nod_rad, 0.0f);
  EXPECT_EQ(m.bell_lift_rad, 0.0f);
  EXPECT_EQ(m.strain, 0.0);
}
