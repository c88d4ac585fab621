// SPDX-License-Identifier: MIT
#include <tutti/components/mouth.hpp>

#include <gtest/gtest.h>

TEST(MouthComponent, DefaultsToRelaxedClosedSilent) {
  const tutti::components::Mouth m;
  EXPECT_EQ(m.tension, 0.0);
  EXPECT_EQ(m.corner_pull, 0.0);
  EXPECT_EQ(m.open, 0.0);
  EXPECT_FALSE(m.buzzing);
}
