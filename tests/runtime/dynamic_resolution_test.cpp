// SPDX-License-Identifier: MIT
// The 3D view's scale chosen from the last frames' cost: it settles where the frame time meets
// the target, does not hunt once there, and stays within its bounds when the target cannot be met.
#include <tutti/runtime/dynamic_resolution.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tutti::runtime {
namespace {

// A device whose frame costs `fixed_s` plus `pixels_s` at full size, scaled by the pixels.
double frame_cost(double fixed_s, double pixels_s, float scale) {
  return fixed_s + pixels_s * static_cast<double>(scale) * static_cast<double>(scale);
}

TEST(DynamicResolution, AFastDeviceKeepsTheFullView) {
  DynamicResolution resolution;
  for (int i = 0; i < 200; ++i) resolution.update(0.010);
  EXPECT_EQ(resolution.scale(), 1.0f);
}

TEST(DynamicResolution, ASlowDeviceSettlesWhereTheTargetIsMet) {
  DynamicResolution resolution({.target_frame_s = 1.0 / 30.0});
  // 80 ms a frame at full size (lavapipe at 720p), 12 ms of it not in the pixels.
  float scale = resolution.scale();
  float settled_at = 0.0f;
  int unchanged = 0;
  for (int i = 0; i < 400; ++i) {
    const float next = resolution.update(frame_cost(0.012, 0.068, scale));
    unchanged = next == scale ? unchanged + 1 : 0;
    scale = next;
    if (unchanged == 100) settled_at = scale;
  }
  ASSERT_GT(settled_at, 0.0f) << "it never stopped moving";
  EXPECT_GE(scale, 0.5f);
  EXPECT_LT(scale, 1.0f);
  const double frame_s = frame_cost(0.012, 0.068, scale);
  EXPECT_LE(frame_s, 1.0 / 30.0 * 1.1) << "scale " << scale;
  EXPECT_GE(frame_s, 1.0 / 30.0 * 0.8) << "no more pixels given up than needed; scale " << scale;
  EXPECT_EQ(std::fmod(scale * 32.0f, 1.0f), 0.0f) << "a multiple of 1/32";
}

TEST(DynamicResolution, AnUnreachableTargetStopsAtTheFloorAndComesBackWhenFaster) {
  DynamicResolution resolution;
  for (int i = 0; i < 300; ++i) resolution.update(0.200);
  EXPECT_EQ(resolution.scale(), 0.5f);
  for (int i = 0; i < 300; ++i) resolution.update(0.005);
  EXPECT_EQ(resolution.scale(), 1.0f);
}

TEST(DynamicResolution, NonsenseTimesChangeNothing) {
  DynamicResolution resolution;
  for (int i = 0; i < 10; ++i) resolution.update(0.2);
  const float before = resolution.scale();
  resolution.update(std::numeric_limits<double>::quiet_NaN());
  resolution.update(-1.0);
  resolution.update(0.0);
  EXPECT_EQ(resolution.scale(), before);
}

}  // namespace
}  // namespace tutti::runtime
