// SPDX-License-Identifier: MIT
#include <tutti/components/finger.hpp>

#include <gtest/gtest.h>

TEST(FingerComponent, DefaultsAreAStraightUnpressedThumb) {
  const tutti::components::Finger f;
  EXPECT_TRUE(f.hand.is_null());
  EXPECT_GE(f.finger, 1);
  EXPECT_LE(f.finger, 5);
  EXPECT_EQ(f.spread_rad, 0.0);
  EXPECT_EQ(f.abduction_rad, 0.0);
  EXPECT_EQ(f.mcp_flexion_rad, 0.0);
  EXPECT_EQ(f.pip_flexion_rad, 0.0);
  EXPECT_EQ(f.dip_flexion_rad, 0.0);
  EXPECT_EQ(f.press_depth, 0.0);
}
