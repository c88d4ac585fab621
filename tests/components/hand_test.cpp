// SPDX-License-Identifier: MIT
#include <tutti/components/hand.hpp>

#include <gtest/gtest.h>

TEST(HandComponent, DefaultsAreAtRestAndUndriven) {
  const tutti::components::Hand h;
  EXPECT_EQ(h.side, tutti::components::HandSide::right);
  EXPECT_TRUE(h.performer.is_null());
  EXPECT_EQ(h.x_mm, 0.0);
  EXPECT_EQ(h.v_x_mm_per_s, 0.0);
  EXPECT_EQ(h.rotation.w, 1.0);
}
