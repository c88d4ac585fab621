// SPDX-License-Identifier: MIT
#pragma once
// How far each finger joint may turn (content/generator/hand_rig.json's joint_limits_deg), and
// the one reading of a joint's flexion and spread that the posing code clamps to and check-pose
// measures against. Tutti's finger conventions (fingertip_reach.hpp): the child's rest offset
// turned by the joint's local rotation; flexion about the hand's flexion axis (local -Z on the
// left hand, +Z on the right), spread > 0 toward the little finger (local -Z on both hands).

#include <array>
#include <filesystem>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <tutti/core/result.hpp>

namespace tutti::stage {

// Degrees. A joint without spread in the file (the middle and outer ones) may not spread.
struct FingerJointLimit {
  double flexion_min_deg = -180.0, flexion_max_deg = 180.0;
  double spread_min_deg = 0.0, spread_max_deg = 0.0;
};

// [thumb .. little][joint from the knuckle out].
using FingerJointLimits = std::array<std::array<FingerJointLimit, 3>, 5>;

// content_dir/generator/hand_rig.json (the default content folder when empty).
Result<FingerJointLimits> load_finger_joint_limits(const std::filesystem::path& content_dir);

struct FlexionSpread {
  double flexion_deg = 0.0;
  double spread_deg = 0.0;
};

// A joint turned by `rotation` (its local rotation), read on its child's rest offset.
FlexionSpread flexion_and_spread(const glm::quat& rotation, const glm::vec3& child_rest, int side);

// How far the joint is past its limits (degrees; 0 within them).
double past_limit(const glm::quat& rotation, const glm::vec3& child_rest, int side,
                  const FingerJointLimit& limit);

// The rotation turned, as little as it takes, back within the limits: spread first (out of the
// flexion plane), then flexion (about its axis).
glm::quat clamp_to_limit(const glm::quat& rotation, const glm::vec3& child_rest, int side,
                         const FingerJointLimit& limit);

}  // namespace tutti::stage
