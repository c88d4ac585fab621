// SPDX-License-Identifier: MIT
#include <tutti/stage/performer_rig.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <string>

namespace tutti::stage {
Result<BodyNodes> find_body_nodes(const model::ModelAsset& asset, const MappedModel& body) {
  BodyNodes n;
  int* const slots[] = {&n.hips,         &n.spine,           &n.chest,           &n.neck,
                        &n.head,         &n.mouth,           &n.arm_left.upper,  &n.arm_left.lower,
                        &n.arm_left.end, &n.arm_right.upper, &n.arm_right.lower, &n.arm_right.end,
                        &n.thigh_left,   &n.thigh_right,     &n.shin_left,       &n.shin_right,
                        &n.grip_left,    &n.grip_right};
  const char* const roles[] = {"hips",      "spine",       "chest",     "neck",    "head",
                               "mouth",     "upper_arm_l", "forearm_l", "hand_l",  "upper_arm_r",
                               "forearm_r", "hand_r",      "thigh_l",   "thigh_r", "shin_l",
                               "shin_r",    "grip_l",      "grip_r"};
  for (std::size_t i = 0; i < std::size(roles); ++i) {
    auto node = find_role(asset, body, roles[i]);
    if (!node) return node.error();
    *slots[i] = *node;
  }
  int* const optional_slots[] = {&n.foot_left, &n.foot_right, &n.toe_left, &n.toe_right};
  const char* const optional_roles[] = {"foot_l", "foot_r", "toe_l", "toe_r"};
  for (std::size_t i = 0; i < std::size(optional_roles); ++i) {
    auto node = find_role(asset, body, optional_roles[i]);
    *optional_slots[i] = node ? *node : -1;
  }
  const char* const finger_names[5] = {"thumb", "index", "middle", "ring", "little"};
  for (std::size_t side = 0; side < 2; ++side) {
    for (std::size_t f = 0; f < 5; ++f) {
      for (std::size_t s = 0; s < 3; ++s) {
        auto node = find_role(
            asset, body,
            std::string(finger_names[f]) + "_" + std::to_string(s + 1) + (side == 0 ? "_l" : "_r"));
        if (!node) return node.error();
        n.fingers[side][f][s] = *node;
      }
      auto tip = find_role(asset, body, std::string(finger_names[f]) + "_tip" + (side == 0 ? "_l" : "_r"));
      n.fingertips[side][f] = tip ? *tip : -1;
    }
  }
  n.morph_tension = morph_index(asset, body.morph_name("tension"));
  n.morph_open = morph_index(asset, body.morph_name("open"));
  return n;
}

glm::vec3 origin(const glm::mat4& m) { return glm::vec3(m[3]); }

glm::quat rotation_of(const glm::mat4& m) {
  glm::mat3 r(m);
  r[0] = glm::normalize(r[0]);
  r[1] = glm::normalize(r[1]);
  r[2] = glm::normalize(r[2]);
  return glm::normalize(glm::quat_cast(r));
}

void reset_pose(const model::ModelAsset& asset, model::ModelPose& pose) {
  for (std::size_t n = 0; n < asset.nodes.size(); ++n) pose.local[n] = asset.nodes[n].rest;
  std::fill(pose.morph_weights.begin(), pose.morph_weights.end(), 0.0f);
}

void turn(model::ModelPose& pose, int node, float radians, const glm::vec3& axis) {
  if (node < 0) return;
  glm::quat& r = pose.local[static_cast<std::size_t>(node)].rotation;
  r = glm::normalize(r * glm::angleAxis(radians, axis));
}

void move(model::ModelPose& pose, int node, const glm::vec3& delta) {
  if (node < 0) return;
  glm::vec3& t = pose.local[static_cast<std::size_t>(node)].translation;
  // Only the components that move: adding 0 would turn a -0 into +0 in the exports.
  for (int c = 0; c < 3; ++c) {
    if (delta[c] != 0.0f) t[c] += delta[c];
  }
}

// A bone's length at rest: its offset from its parent.
float rest_length(const model::ModelAsset& body, int node) {
  return glm::length(body.nodes[static_cast<std::size_t>(node)].rest.translation);
}

void set_morph(model::ModelPose& pose, int index, double value) {
  if (index >= 0) {
    pose.morph_weights[static_cast<std::size_t>(index)] =
        static_cast<float>(std::clamp(value, 0.0, 1.0));
  }
}

components::Transform stage_transform(const scene::Vec3& position_m, double facing_deg) {
  components::Transform t;
  t.x_mm = position_m.x * 1000.0;
  t.y_mm = position_m.y * 1000.0;
  t.z_mm = position_m.z * 1000.0;
  const double half = facing_deg * 3.14159265358979323846 / 360.0;
  t.rotation = {std::cos(half), 0.0, std::sin(half), 0.0};
  return t;
}

void pose_body_base(const BodyNodes& n, bool seated, const model::ModelAsset& body,
                    const components::Breath* breath, model::ModelPose& pose) {
  if (seated) {
    // Thighs forward, shins down again, the hips lowered onto a 460 mm seat.
    turn(pose, n.thigh_left, -std::numbers::pi_v<float> / 2, {1, 0, 0});
    turn(pose, n.thigh_right, -std::numbers::pi_v<float> / 2, {1, 0, 0});
    turn(pose, n.shin_left, std::numbers::pi_v<float> / 2, {1, 0, 0});
    turn(pose, n.shin_right, std::numbers::pi_v<float> / 2, {1, 0, 0});
    if (n.hips >= 0 && n.thigh_left >= 0 && n.shin_left >= 0) {
      const float thigh_length = rest_length(body, n.shin_left);
      move(pose, n.hips, {0.0f, -thigh_length * 0.92f, -0.05f});
    }
  }
  if (breath != nullptr) {
    // Inhaling lifts the chest and leans back a little; the preparation before a long rest's
    // breath starts the motion early.
    const float lift = static_cast<float>(std::max(breath->inhale, 0.5 * breath->preparing));
    turn(pose, n.chest, -0.06f * lift, {1, 0, 0});
    turn(pose, n.neck, 0.04f * lift, {1, 0, 0});
  }
}

void pose_body_motion(const BodyNodes& n, bool seated, const model::ModelAsset& body,
                      const components::BodyMotion& m, model::ModelPose& pose) {
  if (n.hips >= 0) {
    glm::vec3 shift{m.hips_shift_m, 0.0f, 0.0f};
    if (!seated && m.knee_flex_m > 0.0f && n.shin_left >= 0) {
      // Thigh forward and shin back by the same angle keep the feet where they were.
      const float leg = rest_length(body, n.shin_left);
      const float angle = std::acos(std::clamp(1.0f - m.knee_flex_m / (2.0f * leg), 0.5f, 1.0f));
      for (int thigh : {n.thigh_left, n.thigh_right}) turn(pose, thigh, -angle, {1, 0, 0});
      for (int shin : {n.shin_left, n.shin_right}) turn(pose, shin, 2.0f * angle, {1, 0, 0});
      shift.y -= 2.0f * leg * (1.0f - std::cos(angle));
    }
    move(pose, n.hips, shift);
  }
  turn(pose, n.spine, -m.sway_rad, {0, 0, 1});
  turn(pose, n.spine, m.twist_rad, {0, 1, 0});
  turn(pose, n.chest, -m.lean_back_rad, {1, 0, 0});
  turn(pose, n.neck, 0.6f * m.lean_back_rad, {1, 0, 0});
  move(pose, n.chest, {0.0f, m.shoulder_lift_m, 0.0f});
  turn(pose, n.head, m.head_nod_rad, {1, 0, 0});
}

}  // namespace tutti::stage
