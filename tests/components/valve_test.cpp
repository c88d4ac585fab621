// SPDX-License-Identifier: MIT
#include <tutti/components/valve.hpp>

#include <gtest/gtest.h>

TEST(ValveComponent, DefaultsToNoValvesAllUp) {
  const tutti::components::Valve v;
  EXPECT_EQ(v.count, 0);
  for (float press : v.press) EXPECT_EQ(press, 0.0f);
  EXPECT_GE(tutti::components::Valve::kMax, 5);  // 4 valves + a thumb valve
}
