// SPDX-License-Identifier: MIT
#pragma once
// Hands placed by their fingertips: index, middle and ring on three buttons, or five on keys.
// The hand's frame comes from the buttons and the instrument's up, the wrist
// goes where a nominal curl puts the fingertips over the buttons, and each finger is then solved
// onto its button (PIP and DIP bend together to match the reach, the knuckle aims the finger).
// Works on tutti's conventions (identity rest rotations, fingers along the hand's -Y, the index
// toward +Z, flexion about ±Z): its performer, and the stand-in for a user's rig.

#include <array>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <tutti/model/model_asset.hpp>
#include <tutti/stage/finger_joint_limits.hpp>
#include <tutti/stage/performer_rig.hpp>
#include <vector>

namespace tutti::stage {

// How a hand's fingers curl when nothing places them (radians of flexion), and how the nominal
// curl that places the wrist bends them.
struct FingerCurls {
  std::array<float, 3> finger{};  // MCP, PIP, DIP of the index .. little fingers
  std::array<float, 3> little{};  // the little finger's own, when `little_own`
  bool little_own = false;
  float thumb = 0.0f;  // its two outer joints
  // The thumb turned in at its base, about the palm's normal, toward the index; 0: the rig's rest.
  float thumb_adduct = 0.0f;
};

// The fingertip pad's radius, thumb .. little (content/generator/hand_rig.json: the finger's
// radius × its tip ratio): the rounded cap whose outermost point is the tip node.
inline constexpr float kFingertipPadRadiusM[5] = {0.0105f * 0.78f, 0.009f * 0.78f, 0.009f * 0.78f,
                                                  0.009f * 0.78f, 0.0075f * 0.78f};

struct FingertipTargets {
  std::array<bool, 5> has{};
  std::array<glm::vec3, 5> world{};  // where each fingertip node should be
};

// The hand's world rotation: ring→index along the targets' line, the metacarpals up the
// instrument's `up`, leaning `lean` radians over toward the instrument.
glm::quat fingertip_hand_rotation(const FingertipTargets& targets, const glm::vec3& instrument_up,
                                  int side, float lean);

// Where the wrist goes so that, with the hand turned to `hand_rotation` and the targeted fingers
// at the nominal curl, the fingertips' mean lands on the targets' mean.
glm::vec3 fingertip_wrist(const model::ModelAsset& body, const BodyNodes& nodes, int side,
                          const FingerCurls& curls, const FingertipTargets& targets,
                          const glm::quat& hand_rotation, float body_scale);

// Bends each targeted finger so its tip reaches its target (as far as the joints allow); the
// other fingers take their curl. `world` holds the body's world matrices with the hand
// already placed; the finger nodes' local rotations are rewritten. With `limits`, a knuckle that
// would have to turn past its limits to reach its target stops at them (the tip then falls short
// of the target: a hovering finger's target may lie where no hand can put it).
void pose_fingers(const model::ModelAsset& body, const BodyNodes& nodes, int side,
                  const FingerCurls& curls, const FingertipTargets* targets,
                  const FingerJointLimits* limits, const std::vector<glm::mat4>& world,
                  model::ModelPose& pose);

}  // namespace tutti::stage
