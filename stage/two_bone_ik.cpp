// SPDX-License-Identifier: MIT
#include <tutti/stage/two_bone_ik.hpp>

#include <algorithm>
#include <cmath>
#include <glm/gtc/quaternion.hpp>

#include <tutti/model/world_matrices_below.hpp>
#include <tutti/stage/performer_rig.hpp>

namespace tutti::stage {
namespace {

// Sets node's local rotation so that its world rotation becomes `wanted`.
void set_world_rotation(const model::ModelAsset& asset, int node, const glm::quat& wanted,
                        std::span<const glm::mat4> world, const glm::mat4& root,
                        model::ModelPose& pose) {
  const int parent = asset.nodes[static_cast<std::size_t>(node)].parent;
  const glm::quat parent_rotation =
      parent >= 0 ? rotation_of(world[static_cast<std::size_t>(parent)]) : rotation_of(root);
  pose.local[static_cast<std::size_t>(node)].rotation =
      glm::normalize(glm::inverse(parent_rotation) * wanted);
}

// The three joints' world matrices after the upper one turned, the same products a whole pass
// makes, when the chain is a chain (each joint the parent of the next); else everything below.
// The hand and fingers below the end are brought up to date once, at the end of the solve.
void update_chain(const model::ModelAsset& asset, const model::ModelPose& pose,
                  const glm::mat4& root, const TwoBoneChain& chain, std::span<glm::mat4> world) {
  const auto u = static_cast<std::size_t>(chain.upper);
  const auto l = static_cast<std::size_t>(chain.lower);
  const auto e = static_cast<std::size_t>(chain.end);
  const int above = asset.nodes[u].parent;
  if (asset.nodes[l].parent != chain.upper || asset.nodes[e].parent != chain.lower ||
      !(above < chain.upper) || !(u < l && l < e) || e >= pose.local.size() || e >= world.size()) {
    model::update_world_matrices_below(asset, pose, root, chain.upper, world);
    return;
  }
  world[u] = (above >= 0 ? world[static_cast<std::size_t>(above)] : root) * model::to_matrix(pose.local[u]);
  world[l] = world[u] * model::to_matrix(pose.local[l]);
  world[e] = world[l] * model::to_matrix(pose.local[e]);
}

}  // namespace

glm::quat rotation_between(const glm::vec3& from, const glm::vec3& to) {
  const float cosine = std::clamp(glm::dot(from, to), -1.0f, 1.0f);
  if (cosine > 0.999999f) return glm::quat(1, 0, 0, 0);
  if (cosine < -0.999999f) {
    glm::vec3 axis = glm::cross(glm::vec3(1, 0, 0), from);
    if (glm::dot(axis, axis) < 1e-8f) axis = glm::cross(glm::vec3(0, 1, 0), from);
    return glm::angleAxis(3.14159265f, glm::normalize(axis));
  }
  const glm::vec3 axis = glm::normalize(glm::cross(from, to));
  return glm::angleAxis(std::acos(cosine), axis);
}

void solve_two_bone_ik(const model::ModelAsset& asset, const TwoBoneChain& chain,
                       const glm::vec3& target, const glm::vec3& pole, const glm::mat4& root,
                       model::ModelPose& pose, std::span<glm::mat4> world, float soft_m) {
  if (chain.upper < 0 || chain.lower < 0 || chain.end < 0) return;
  const auto u = static_cast<std::size_t>(chain.upper);
  const auto l = static_cast<std::size_t>(chain.lower);
  const auto e = static_cast<std::size_t>(chain.end);
  const glm::vec3 a = origin(world[u]);
  const glm::vec3 b = origin(world[l]);
  const glm::vec3 c = origin(world[e]);
  const float upper_length = glm::length(b - a);
  const float lower_length = glm::length(c - b);
  const glm::vec3 to_target = target - a;
  const float reach = glm::length(to_target);
  if (upper_length < 1e-5f || lower_length < 1e-5f || reach < 1e-5f) return;

  const float full = upper_length + lower_length;
  float eased = reach;
  if (soft_m > 0.0f && reach > full - soft_m) {
    eased = full - soft_m * std::exp(-(reach - (full - soft_m)) / soft_m);
  }
  const float d = std::clamp(eased, std::abs(upper_length - lower_length) + 1e-4f, full - 1e-4f);
  const glm::vec3 axis = to_target / reach;
  glm::vec3 bend = pole - glm::dot(pole, axis) * axis;
  if (glm::dot(bend, bend) < 1e-10f) {
    bend = (b - a) - glm::dot(b - a, axis) * axis;
    if (glm::dot(bend, bend) < 1e-10f) return;
  }
  bend = glm::normalize(bend);
  const float cos_shoulder =
      std::clamp((upper_length * upper_length + d * d - lower_length * lower_length) /
                     (2.0f * upper_length * d),
                 -1.0f, 1.0f);
  const float shoulder_angle = std::acos(cos_shoulder);
  const glm::vec3 elbow =
      a + upper_length * (std::cos(shoulder_angle) * axis + std::sin(shoulder_angle) * bend);

  const glm::quat turn_upper = rotation_between(glm::normalize(b - a), glm::normalize(elbow - a));
  const glm::quat upper_world = turn_upper * rotation_of(world[u]);
  set_world_rotation(asset, chain.upper, upper_world, world, root, pose);
  update_chain(asset, pose, root, chain, world);

  const glm::vec3 new_elbow = origin(world[l]);
  const glm::vec3 new_end = origin(world[e]);
  const glm::vec3 wanted_end = a + axis * d;
  const glm::quat turn_lower =
      rotation_between(glm::normalize(new_end - new_elbow), glm::normalize(wanted_end - new_elbow));
  const glm::quat lower_world = turn_lower * rotation_of(world[l]);
  set_world_rotation(asset, chain.lower, lower_world, world, root, pose);
  model::update_world_matrices_below(asset, pose, root, chain.upper, world);
}

}  // namespace tutti::stage
