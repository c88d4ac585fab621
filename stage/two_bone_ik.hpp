// SPDX-License-Identifier: MIT
#pragma once
// Analytic two-bone IK (shoulder → elbow → wrist) on a posed model: turns the upper and the lower
// bone so the end of the chain reaches a world-space target, the elbow bending toward a pole
// direction. Used to put hands on instruments and keyboards. Pure: the same pose and target give
// the same result.

#include <glm/glm.hpp>
#include <span>

#include <tutti/model/model_asset.hpp>

namespace tutti::stage {

struct TwoBoneChain {
  int upper = -1;  // node rotated at the shoulder
  int lower = -1;  // its child, rotated at the elbow
  int end = -1;    // the lower bone's child whose origin should reach the target (wrist)
};

// Rewrites pose.local[upper].rotation and pose.local[lower].rotation. `world` must hold the
// world matrices of the current pose (compute_world_matrices); it is updated before returning
// (only below the upper node: nothing else moved, model/world_matrices_below.hpp). A target out of reach straightens the arm toward it. Nodes missing (-1) or
// degenerate chains leave the pose as it is. `soft_m` > 0: the last soft_m of the arm's reach is
// eased (soft IK): the end stops short of a target near or past full stretch by up to soft_m / e
// at full stretch, and the elbow never whips straight however the target moves there (at full
// stretch an elbow's angle changes without bound for a small move of the hand).
void solve_two_bone_ik(const model::ModelAsset& asset, const TwoBoneChain& chain,
                       const glm::vec3& target, const glm::vec3& pole, const glm::mat4& root,
                       model::ModelPose& pose, std::span<glm::mat4> world, float soft_m = 0.0f);

// The rotation taking unit vector `from` onto unit vector `to` (shortest arc).
glm::quat rotation_between(const glm::vec3& from, const glm::vec3& to);

}  // namespace tutti::stage
