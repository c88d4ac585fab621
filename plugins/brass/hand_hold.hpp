#pragma once
// Hands placed by their fingertips: a right hand whose index, middle and ring fingertips rest on
// three valve buttons. The hand's frame comes from the buttons and the instrument's up, the wrist
// goes where a nominal curl puts the fingertips over the buttons, and each finger is then solved
// onto its button (PIP and DIP bend together to match the reach, the knuckle aims the finger).
// Works on tutti's default rig (identity rest rotations, fingers along the hand's -Y, the index
// toward +Z, flexion about ±Z).

#include <array>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <tutti/brass/hold.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/stage/performer_rig.hpp>

namespace tutti::brass_family {

struct FingertipTargets {
  std::array<bool, 5> has{};
  std::array<glm::vec3, 5> world{};  // where each fingertip node should be
};

// The hand's world rotation: ring→index along the targets' line, the metacarpals up the
// instrument's `up`, leaning `lean` radians over toward the instrument.
glm::quat fingertip_hand_rotation(const FingertipTargets& targets, const glm::vec3& instrument_up,
                                  int side, float lean);

// Where the wrist goes so that, with the hand turned to `hand_rotation` and the targeted fingers
// at the hold's nominal curl, the fingertips' mean lands on the targets' mean.
glm::vec3 fingertip_wrist(const model::ModelAsset& body, const stage::BodyNodes& nodes, int side,
                          const HandHold& hold, const FingertipTargets& targets,
                          const glm::quat& hand_rotation, float body_scale);

// Bends each targeted finger so its tip reaches its target (as far as the joints allow); the
// other fingers take the hold's curl. `world` holds the body's world matrices with the hand
// already placed; the finger nodes' local rotations are rewritten.
void pose_fingers(const model::ModelAsset& body, const stage::BodyNodes& nodes, int side,
                  const HandHold& hold, const FingertipTargets* targets,
                  const std::vector<glm::mat4>& world, model::ModelPose& pose);

}  // namespace tutti::brass_family
