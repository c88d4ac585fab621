// SPDX-License-Identifier: MIT
// Two-bone IK on a bare arm (shoulder, elbow, wrist; 0.3 m and 0.25 m bones hanging down): the
// wrist reaches targets within reach, and with a soft reach the elbow straightens smoothly as a
// target moves out past full stretch, instead of whipping straight.
#include <tutti/stage/two_bone_ik.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace tutti::stage {
namespace {

struct Arm {
  model::ModelAsset asset;
  TwoBoneChain chain{0, 1, 2};
  Arm() {
    asset.nodes.resize(3);
    asset.nodes[0].name = "upper";
    asset.nodes[1].name = "lower";
    asset.nodes[1].parent = 0;
    asset.nodes[1].rest.translation = {0.0f, -0.3f, 0.0f};
    asset.nodes[2].name = "wrist";
    asset.nodes[2].parent = 1;
    asset.nodes[2].rest.translation = {0.0f, -0.25f, 0.0f};
    asset.roots = {0};
  }
  // The wrist's position and the elbow's angle (degrees, 0 = straight) after solving for target.
  std::pair<glm::vec3, double> solve(const glm::vec3& target, float soft_m) const {
    model::ModelPose pose;
    pose.local.resize(3);
    for (std::size_t n = 0; n < 3; ++n) pose.local[n] = asset.nodes[n].rest;
    std::vector<glm::mat4> world(3);
    model::compute_world_matrices(asset, pose, glm::mat4(1.0f), world);
    solve_two_bone_ik(asset, chain, target, glm::vec3(0, 0, -1), glm::mat4(1.0f), pose, world,
                      soft_m);
    const glm::vec3 shoulder(world[0][3]), elbow(world[1][3]), wrist(world[2][3]);
    const double cosine = glm::dot(glm::normalize(elbow - shoulder), glm::normalize(wrist - elbow));
    return {wrist, std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / 3.14159265358979};
  }
};

TEST(TwoBoneIk, TheWristReachesATargetWithinReach) {
  const Arm arm;
  for (const glm::vec3 target : {glm::vec3(0.1f, -0.3f, 0.2f), glm::vec3(0.0f, -0.2f, 0.35f)}) {
    for (const float soft : {0.0f, 0.015f}) {
      const auto [wrist, bend] = arm.solve(target, soft);
      EXPECT_LT(glm::distance(wrist, target), 1e-4f) << soft;
      EXPECT_GT(bend, 10.0);
    }
  }
}

// A target moving out along the arm at a steady speed, 1 mm a step, from 40 mm inside full
// stretch to 40 mm past it. Hard: the elbow's angle turns most (over 4 degrees) in the last millimetre
// before straight. Soft (15 mm): it never turns more than a few degrees a step, the wrist stops short
// of a target at full stretch by no more than soft / e, and reaches any target 15 mm inside.
TEST(TwoBoneIk, ASoftReachStraightensTheElbowSmoothly) {
  const Arm arm;
  const glm::vec3 direction = glm::normalize(glm::vec3(0.0f, -0.4f, 1.0f));
  double hard_step = 0.0, soft_step = 0.0;
  double last_hard = -1.0, last_soft = -1.0;
  for (int mm = -40; mm <= 40; ++mm) {
    const glm::vec3 target = direction * (0.55f + static_cast<float>(mm) / 1000.0f);
    const double hard = arm.solve(target, 0.0f).second;
    const auto [wrist, soft] = arm.solve(target, 0.015f);
    if (last_hard >= 0.0) hard_step = std::max(hard_step, std::abs(hard - last_hard));
    if (last_soft >= 0.0) soft_step = std::max(soft_step, std::abs(soft - last_soft));
    last_hard = hard;
    last_soft = soft;
    if (mm == 0) {
      EXPECT_LE(glm::distance(wrist, target), 0.015f / 2.718f + 1e-4f);
    }
    if (mm <= -15) {
      EXPECT_LT(glm::distance(wrist, target), 1e-4f) << mm;
    }
  }
  EXPECT_GT(hard_step, 4.0);
  EXPECT_LT(soft_step, 0.5 * hard_step) << soft_step << " vs " << hard_step;
}

}  // namespace
}  // namespace tutti::stage
