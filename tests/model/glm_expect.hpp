// SPDX-License-Identifier: MIT
#pragma once
// Shared by the model tests: GoogleTest expectations on GLM vectors and matrices, component by
// component.

#include <gtest/gtest.h>

#include <glm/glm.hpp>

namespace tutti::test {

inline void expect_near(const glm::vec3& actual, const glm::vec3& expected,
                        float tolerance = 1e-5f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

inline void expect_near(const glm::vec4& actual, const glm::vec4& expected,
                        float tolerance = 1e-5f) {
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << i;
}

inline void expect_near(const glm::mat4& actual, const glm::mat4& expected,
                        float tolerance = 1e-5f) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(actual[c][r], expected[c][r], tolerance) << c << r;
  }
}

}  // namespace tutti::test
