// SPDX-License-Identifier: MIT
#include <tutti/components/transform.hpp>

#include <gtest/gtest.h>

TEST(TransformComponent, DefaultIsOriginAndIdentity) {
  const tutti::components::Transform t;
  EXPECT_EQ(t.x_mm, 0.0);
  EXPECT_EQ(t.y_mm, 0.0);
  EXPECT_EQ(t.z_mm, 0.0);
  EXPECT_EQ(t.rotation.w, 1.0);
  EXPECT_EQ(t.rotation.x, 0.0);
  EXPECT_EQ(t.rotation.y, 0.0);
  EXPECT_EQ(t.rotation.z, 0.0);
}
