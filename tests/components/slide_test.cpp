// SPDX-License-Identifier: MIT
#include <tutti/components/slide.hpp>

#include <gtest/gtest.h>

TEST(SlideComponent, DefaultsToFirstPositionAtRest) {
  const tutti::components::Slide s;
  EXPECT_EQ(s.extension_mm, 0.0);
  EXPECT_EQ(s.position, 1.0);
  EXPECT_EQ(s.speed_mm_per_s, 0.0);
}
