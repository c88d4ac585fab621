// SPDX-License-Identifier: MIT
// Includes only its header first: it must compile on its own.
#include <tutti/components/hand_side.hpp>

#include <gtest/gtest.h>

TEST(HandSideComponent, DefaultsToRight) {
  EXPECT_EQ(tutti::components::HandSide{}, tutti::components::HandSide::right);
}
