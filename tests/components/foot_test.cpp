// SPDX-License-Identifier: MIT
#include <tutti/components/foot.hpp>

#include <gtest/gtest.h>

TEST(FootComponent, DefaultsAreAFootWithNothingToPlay) {
  const tutti::components::Foot f;
  EXPECT_TRUE(f.performer.is_null());
  EXPECT_EQ(f.from_key, -1);
  EXPECT_EQ(f.to_key, -1);
  EXPECT_EQ(f.key, -1);
  EXPECT_EQ(f.press_depth, 0.0);
  EXPECT_EQ(f.travel, 0.0);
  EXPECT_EQ(f.lift_m, 0.0);
}
