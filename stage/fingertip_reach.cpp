// SPDX-License-Identifier: MIT
#include <tutti/stage/fingertip_reach.hpp>

#include <algorithm>
#include <cmath>

#include <tutti/stage/two_bone_ik.hpp>

namespace tutti::stage {
namespace {

constexpr std::size_t kTip = 3;  // fingertip node index in a finger's chain below

// The default rig flexes the left hand's fingers about local -Z, the right's about +Z
// (content/generator/README.md).
glm::vec3 flex_axis(int side) { return side == 0 ? glm::vec3(0, 0, -1) : glm::vec3(0, 0, 1); }

struct FingerChain {
  std::array<int, 4> node{-1, -1, -1, -1};  // MCP, PIP, DIP, tip
  std::array<glm::vec3, 4> offset{};        // each node's rest translation (its parent's frame)
  bool valid() const { return node[0] >= 0 && node[1] >= 0 && node[2] >= 0 && node[3] >= 0; }
};

FingerChain chain_of(const model::ModelAsset& body, const BodyNodes& nodes, int side,
                     std::size_t f) {
  FingerChain c;
  for (std::size_t s = 0; s < 3; ++s) {
    c.node[s] = nodes.fingers[static_cast<std::size_t>(side)][f][s];
  }
  c.node[kTip] = nodes.fingertips[static_cast<std::size_t>(side)][f];
  if (!c.valid()) return c;
  for (std::size_t s = 0; s < 4; ++s) {
    c.offset[s] = body.nodes[static_cast<std::size_t>(c.node[s])].rest.translation;
  }
  return c;
}

// The tip relative to the MCP joint, in the MCP's frame, with PIP and DIP bent by `pip`, `dip`.
glm::vec3 tip_from_mcp(const FingerChain& c, const glm::vec3& axis, float pip, float dip) {
  return c.offset[1] + glm::angleAxis(pip, axis) * (c.offset[2] + glm::angleAxis(dip, axis) *
                                                                      c.offset[3]);
}

// Hand-local tip at the curl (MCP, PIP, DIP).
glm::vec3 curled_tip(const FingerChain& c, const glm::vec3& axis, const std::array<float, 3>& curl) {
  return c.offset[0] + glm::angleAxis(curl[0], axis) * tip_from_mcp(c, axis, curl[1], curl[2]);
}

std::array<float, 3> curl_of(const FingerCurls& curls, std::size_t f) {
  if (f == 0) return {0.0f, curls.thumb, curls.thumb};
  return f == 4 && curls.little_own ? curls.little : curls.finger;
}

}  // namespace

glm::quat fingertip_hand_rotation(const FingertipTargets& targets, const glm::vec3& instrument_up,
                                  int side, float lean) {
  // Ring → index: the knuckles' line (index toward +Z on the default rig).
  glm::vec3 first(0.0f), last(0.0f);
  bool have_first = false;
  for (std::size_t f = 1; f < 4; ++f) {
    if (!targets.has[f]) continue;
    if (!have_first) first = targets.world[f];
    have_first = true;
    last = targets.world[f];
  }
  glm::vec3 knuckles = first - last;
  if (glm::length(knuckles) < 1e-6f) knuckles = glm::vec3(0, 0, 1);
  knuckles = glm::normalize(knuckles);
  const glm::vec3 up = glm::normalize(instrument_up - glm::dot(instrument_up, knuckles) * knuckles);
  // The hand's side of the instrument: the player's right for the right hand.
  const glm::vec3 outward = (side == 1 ? 1.0f : -1.0f) * glm::normalize(glm::cross(up, knuckles));
  const glm::vec3 metacarpals = std::cos(lean) * up - std::sin(lean) * outward;
  const glm::vec3 y = -metacarpals;
  const glm::vec3 z = glm::normalize(knuckles - glm::dot(knuckles, y) * y);
  const glm::vec3 x = glm::cross(y, z);
  return glm::normalize(glm::quat_cast(glm::mat3(x, y, z)));
}

glm::vec3 fingertip_wrist(const model::ModelAsset& body, const BodyNodes& nodes, int side,
                          const FingerCurls& curls, const FingertipTargets& targets,
                          const glm::quat& hand_rotation, float body_scale) {
  glm::vec3 tips(0.0f), goals(0.0f);
  int count = 0;
  for (std::size_t f = 0; f < 5; ++f) {
    if (!targets.has[f]) continue;
    const FingerChain c = chain_of(body, nodes, side, f);
    if (!c.valid()) continue;
    tips += curled_tip(c, flex_axis(side), curl_of(curls, f));
    goals += targets.world[f];
    ++count;
  }
  if (count == 0) return goals;
  return goals / static_cast<float>(count) -
         hand_rotation * (body_scale * tips / static_cast<float>(count));
}

void pose_fingers(const model::ModelAsset& body, const BodyNodes& nodes, int side,
                  const FingerCurls& curls, const FingertipTargets* targets,
                  const FingerJointLimits* limits, const std::vector<glm::mat4>& world,
                  model::ModelPose& pose) {
  const glm::vec3 axis = flex_axis(side);
  const auto s = static_cast<std::size_t>(side);
  const int hand = side == 0 ? nodes.arm_left.end : nodes.arm_right.end;
  for (std::size_t f = 0; f < 5; ++f) {
    const auto& bones = nodes.fingers[s][f];
    if (f == 0 && (targets == nullptr || !targets->has[0])) {
      const FingerChain middle = chain_of(body, nodes, side, 2);
      if (curls.thumb_adduct != 0.0f && bones[0] >= 0 && middle.valid()) {
        // The palm's normal in the hand's frame: across the flexion axis and the middle finger.
        const glm::vec3 normal = glm::normalize(glm::cross(axis, middle.offset[0]));
        const auto b = static_cast<std::size_t>(bones[0]);
        pose.local[b].rotation =
            glm::angleAxis(curls.thumb_adduct, normal) * body.nodes[b].rest.rotation;
      }
      for (std::size_t k = 1; k < 3; ++k) {
        if (bones[k] >= 0) {
          pose.local[static_cast<std::size_t>(bones[k])].rotation =
              glm::angleAxis(curls.thumb, axis);
        }
      }
      continue;
    }
    const std::array<float, 3> curl = curl_of(curls, f);
    const FingerChain c = chain_of(body, nodes, side, f);
    if (targets == nullptr || !targets->has[f] || !c.valid() || hand < 0) {
      for (std::size_t k = 0; k < 3; ++k) {
        if (bones[k] >= 0) {
          pose.local[static_cast<std::size_t>(bones[k])].rotation = glm::angleAxis(curl[k], axis);
        }
      }
      continue;
    }
    // The target in the hand's frame (the world matrix carries the body's scale).
    const glm::vec3 goal = glm::vec3(glm::inverse(world[static_cast<std::size_t>(hand)]) *
                                     glm::vec4(targets->world[f], 1.0f));
    const glm::vec3 reach = goal - c.offset[0];
    const float wanted = glm::length(reach);
    // PIP and DIP bend in the curl's ratio; the reach shrinks as they bend: bisect.
    const float ratio = curl[1] > 1e-3f ? curl[2] / curl[1] : 0.6f;  // thumb: IP = MCP
    constexpr float kPipMax = 1.9f;  // 110°, hand_rig.json's PIP limit
    float lo = 0.0f, hi = kPipMax;
    if (glm::length(tip_from_mcp(c, axis, lo, 0.0f)) <= wanted) {
      hi = lo;
    } else if (glm::length(tip_from_mcp(c, axis, hi, ratio * hi)) >= wanted) {
      lo = hi;
    } else {
      for (int i = 0; i < 24; ++i) {
        const float mid = 0.5f * (lo + hi);
        (glm::length(tip_from_mcp(c, axis, mid, ratio * mid)) > wanted ? lo : hi) = mid;
      }
    }
    const float pip = 0.5f * (lo + hi);
    const glm::vec3 bent = tip_from_mcp(c, axis, pip, ratio * pip);
    glm::quat knuckle = rotation_between(glm::normalize(bent), glm::normalize(reach));
    if (limits != nullptr) knuckle = clamp_to_limit(knuckle, c.offset[1], side, (*limits)[f][0]);
    pose.local[static_cast<std::size_t>(c.node[0])].rotation = knuckle;
    pose.local[static_cast<std::size_t>(c.node[1])].rotation = glm::angleAxis(pip, axis);
    pose.local[static_cast<std::size_t>(c.node[2])].rotation = glm::angleAxis(ratio * pip, axis);
  }
}

}  // namespace tutti::stage
