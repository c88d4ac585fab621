// SPDX-License-Identifier: MIT
#include <tutti/components/breath.hpp>

#include <gtest/gtest.h>

TEST(BreathComponent, DefaultsToFullLungsAtRest) {
  const tutti::components::Breath b;
  EXPECT_EQ(b.air, 1.0);
  EXPECT_EQ(b.inhale, 0.0);
  EXPECT_EQ(b.preparing, 0.0);
  EXPECT_EQ(b.strain, 0.0);
  EXPECT_EQ(b.breath_index, -1);
}
