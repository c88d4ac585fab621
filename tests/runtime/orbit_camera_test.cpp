// SPDX-License-Identifier: MIT
#include <tutti/runtime/orbit_camera.hpp>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

namespace tutti::runtime {
namespace {

void expect_near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-4f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

scene::Camera wide() {
  scene::Camera camera;
  camera.name = "wide";
  camera.position_m = {2.0, 1.6, 4.0};
  camera.target_m = {0.0, 1.0, 0.0};
  camera.fov_deg = 35.0;
  return camera;
}

TEST(OrbitCameraTest, StartsWhereTheSceneCameraIs) {
  const OrbitCamera orbit = OrbitCamera::from(wide());
  expect_near(orbit.position(), {2.0f, 1.6f, 4.0f});
  expect_near(orbit.target(), {0.0f, 1.0f, 0.0f});
  EXPECT_FLOAT_EQ(orbit.fov_y_deg(), 35.0f);
  const render::Camera expected =
      render::look_at_camera({2.0f, 1.6f, 4.0f}, {0.0f, 1.0f, 0.0f}, 35.0f, 16.0f / 9.0f);
  const render::Camera got = orbit.camera(16.0f / 9.0f);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(got.view[c][r], expected.view[c][r], 1e-4f);
      EXPECT_NEAR(got.projection[c][r], expected.projection[c][r], 1e-4f);
    }
  }
}

TEST(OrbitCameraTest, OrbitKeepsTheTargetAndTheDistance) {
  OrbitCamera orbit = OrbitCamera::from(wide());
  const float distance = orbit.distance_m();
  const float yaw = orbit.yaw_deg();
  orbit.orbit(100.0f, -20.0f);
  expect_near(orbit.target(), {0.0f, 1.0f, 0.0f});
  EXPECT_NEAR(glm::length(orbit.position() - orbit.target()), distance, 1e-4f);
  EXPECT_NEAR(orbit.yaw_deg(), yaw - 30.0f, 1e-3f);  // 0.3 degrees per pixel
}

TEST(OrbitCameraTest, PitchIsClamped) {
  OrbitCamera orbit = OrbitCamera::from(wide());
  orbit.orbit(0.0f, 1e6f);
  EXPECT_FLOAT_EQ(orbit.pitch_deg(), 85.0f);
  orbit.orbit(0.0f, -1e6f);
  EXPECT_FLOAT_EQ(orbit.pitch_deg(), -85.0f);
  // Straight above the target is clamped on creation too.
  const OrbitCamera above({0.0f, 10.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 40.0f);
  EXPECT_FLOAT_EQ(above.pitch_deg(), 85.0f);
}

TEST(OrbitCameraTest, ZoomScalesTheDistanceWithinItsLimits) {
  OrbitCamera orbit = OrbitCamera::from(wide());
  const float distance = orbit.distance_m();
  orbit.zoom(1.0f);
  EXPECT_NEAR(orbit.distance_m(), distance * 0.9f, 1e-4f);
  orbit.zoom(-2.0f);
  EXPECT_NEAR(orbit.distance_m(), distance / 0.9f, 1e-4f);
  orbit.zoom(1000.0f);
  EXPECT_FLOAT_EQ(orbit.distance_m(), 0.2f);
  orbit.zoom(-1000.0f);
  EXPECT_FLOAT_EQ(orbit.distance_m(), 60.0f);
}

TEST(OrbitCameraTest, PanMovesTheTargetInTheViewPlane) {
  OrbitCamera orbit = OrbitCamera::from(wide());
  const glm::vec3 forward = glm::normalize(orbit.target() - orbit.position());
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
  const glm::vec3 before = orbit.target();
  const float distance = orbit.distance_m();
  orbit.pan(100.0f, 0.0f, 720.0f);
  const glm::vec3 moved = orbit.target() - before;
  EXPECT_NEAR(glm::dot(moved, forward), 0.0f, 1e-4f);
  EXPECT_LT(glm::dot(moved, right), 0.0f);  // the scene follows the pointer right
  // 100 px of a 720 px view at the target's depth.
  const float expected = 100.0f * 2.0f * distance * std::tan(glm::radians(35.0f) / 2) / 720.0f;
  EXPECT_NEAR(glm::length(moved), expected, 1e-4f);
  EXPECT_FLOAT_EQ(orbit.distance_m(), distance);
  orbit.pan(10.0f, 10.0f, 0.0f);  // no viewport: nothing
  expect_near(orbit.target(), before + moved);
}

}  // namespace
}  // namespace tutti::runtime
