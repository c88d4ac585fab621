// SPDX-License-Identifier: MIT
#include <tutti/components/performer.hpp>

#include <gtest/gtest.h>

TEST(PerformerComponent, DefaultsAreEmptyNameSeedZero) {
  const tutti::components::Performer p;
  EXPECT_TRUE(p.name.empty());
  EXPECT_EQ(p.seed, 0U);
}
