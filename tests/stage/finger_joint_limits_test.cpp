// SPDX-License-Identifier: MIT
// Finger joint limits: read from hand_rig.json (bad files named), read off a posed joint the way
// check-pose measures it, and a knuckle turned past them brought back to them, no further.
#include <tutti/stage/finger_joint_limits.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "scratch_dir.hpp"
#include "testdata.hpp"

namespace tutti::stage {
namespace {

constexpr float kDegree = 3.14159265f / 180.0f;
constexpr int kRight = 1;

// The index finger's proximal bone at rest: along the hand's -Y (fingertip_reach.hpp).
const glm::vec3 kBone(0.0f, -0.045f, 0.0f);

// A knuckle spread by `spread` (toward the little finger, local -Z) after flexing by `flexion`.
glm::quat knuckle(float flexion_deg, float spread_deg) {
  const glm::quat flex = glm::angleAxis(flexion_deg * kDegree, glm::vec3(0, 0, 1));
  const glm::vec3 bone = glm::normalize(flex * kBone);
  const glm::vec3 toward_thumb = glm::normalize(glm::cross(bone, glm::vec3(0, 0, 1)));
  return glm::angleAxis(spread_deg * kDegree, -toward_thumb) * flex;
}

TEST(FingerJointLimits, LoadsTheRigsLimits) {
  auto limits = load_finger_joint_limits(tutti::test::source_dir() / "content");
  ASSERT_TRUE(limits) << limits.error().message;
  const FingerJointLimit& index_knuckle = (*limits)[1][0];
  EXPECT_EQ(index_knuckle.flexion_min_deg, -30.0);
  EXPECT_EQ(index_knuckle.flexion_max_deg, 90.0);
  EXPECT_EQ(index_knuckle.spread_min_deg, -20.0);
  EXPECT_EQ(index_knuckle.spread_max_deg, 20.0);
  // The middle joints hinge: no spread.
  EXPECT_EQ((*limits)[1][1].spread_min_deg, 0.0);
  EXPECT_EQ((*limits)[1][1].spread_max_deg, 0.0);
}

TEST(FingerJointLimits, BadFilesAreNamed) {
  tutti::test::ScratchDir dir;
  std::filesystem::create_directories(dir.path() / "generator");
  dir.write("generator/hand_rig.json", R"({"shape_mm": {}})");
  auto missing = load_finger_joint_limits(dir.path());
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("hand_rig.json: /joint_limits_deg: missing"),
            std::string::npos)
      << missing.error().message;

  dir.write("generator/hand_rig.json",
            R"({"joint_limits_deg": {"index_1": {"flexion_min_deg": "a lot"}}})");
  auto not_a_number = load_finger_joint_limits(dir.path());
  ASSERT_FALSE(not_a_number);
  EXPECT_NE(not_a_number.error().message.find("/joint_limits_deg/index_1/flexion_min_deg"),
            std::string::npos)
      << not_a_number.error().message;

  dir.write("generator/hand_rig.json",
            R"({"joint_limits_deg": {"ring_2": {"flexion_min_deg": 50, "flexion_max_deg": 10}}})");
  auto upside_down = load_finger_joint_limits(dir.path());
  ASSERT_FALSE(upside_down);
  EXPECT_NE(upside_down.error().message.find("ring_2: a minimum above its maximum"),
            std::string::npos)
      << upside_down.error().message;

  auto absent = load_finger_joint_limits(dir.path() / "nowhere");
  ASSERT_FALSE(absent);
  EXPECT_NE(absent.error().message.find("hand_rig.json"), std::string::npos);
}

TEST(FingerJointLimits, ReadsFlexionAndSpread) {
  const FlexionSpread read = flexion_and_spread(knuckle(40.0f, 12.0f), kBone, kRight);
  EXPECT_NEAR(read.flexion_deg, 40.0, 0.01);
  EXPECT_NEAR(read.spread_deg, 12.0, 0.01);
  const FlexionSpread rest = flexion_and_spread(glm::quat(1, 0, 0, 0), kBone, kRight);
  EXPECT_NEAR(rest.flexion_deg, 0.0, 1e-6);
  EXPECT_NEAR(rest.spread_deg, 0.0, 1e-6);
}

TEST(FingerJointLimits, AKnucklePastItsLimitsIsBroughtBackToThem) {
  const FingerJointLimit limit{-30.0, 90.0, -20.0, 20.0};
  // 1.2° past the spread toward the thumb (what a seated trumpeter's lifted index did).
  const glm::quat spread_too_far = knuckle(-4.5f, -21.2f);
  EXPECT_NEAR(past_limit(spread_too_far, kBone, kRight, limit), 1.2, 0.01);
  const glm::quat spread_back = clamp_to_limit(spread_too_far, kBone, kRight, limit);
  const FlexionSpread read = flexion_and_spread(spread_back, kBone, kRight);
  EXPECT_NEAR(read.spread_deg, -20.0, 0.01);
  EXPECT_NEAR(read.flexion_deg, -4.5, 0.01);  // the flexion left as it was
  EXPECT_NEAR(past_limit(spread_back, kBone, kRight, limit), 0.0, 0.01);

  // Bent back past its flexion limit, and spread too far the other way: both come back.
  const glm::quat both = clamp_to_limit(knuckle(-45.0f, 30.0f), kBone, kRight, limit);
  const FlexionSpread both_read = flexion_and_spread(both, kBone, kRight);
  EXPECT_NEAR(both_read.flexion_deg, -30.0, 0.01);
  EXPECT_NEAR(both_read.spread_deg, 20.0, 0.01);

  // Within the limits: untouched.
  const glm::quat inside = knuckle(35.0f, 8.0f);
  const glm::quat kept = clamp_to_limit(inside, kBone, kRight, limit);
  EXPECT_NEAR(std::abs(glm::dot(kept, inside)), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace tutti::stage
