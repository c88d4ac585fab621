// SPDX-License-Identifier: MIT
#pragma once
// The performer rig both families pose (content/generator's performer.glb, or the stand-in for a
// user's character, body_retarget.hpp — both with tutti's conventions: identity rest rotations,
// +X the player's left, +Y up, +Z their front): the nodes a family needs of it, and the pose steps
// they share — the seated legs, the breathing chest, the ensemble's body motion — plus small pose
// helpers.

#include <array>
#include <vector>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <tutti/components/body_motion.hpp>
#include <tutti/components/breath.hpp>
#include <tutti/components/transform.hpp>
#include <tutti/core/result.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/scene/scene.hpp>
#include <tutti/stage/model_binding.hpp>
#include <tutti/stage/two_bone_ik.hpp>

namespace tutti::stage {

// Node indices in the performer rig (-1 where the model lacks one).
struct BodyNodes {
  int hips = -1, spine = -1, chest = -1, neck = -1, head = -1, mouth = -1;
  int grip_left = -1, grip_right = -1;  // palm centres, turned into the hand asset's frame
  TwoBoneChain arm_left, arm_right;
  int thigh_left = -1, thigh_right = -1, shin_left = -1, shin_right = -1;
  // The feet (ankles) and where a sole presses a pedal (tutti's rig: toe_l, toe_r); -1 = none.
  int foot_left = -1, foot_right = -1, toe_left = -1, toe_right = -1;
  int morph_tension = -1, morph_open = -1;  // indices into the pose's morph_weights
  // Finger bones [left, right][thumb .. little][segment], for the grip curls.
  std::array<std::array<std::array<int, 3>, 5>, 2> fingers{};
  // Their tips' nodes [left, right][thumb .. little] (-1 when the rig has none).
  std::array<std::array<int, 5>, 2> fingertips{};
};

Result<BodyNodes> find_body_nodes(const model::ModelAsset& asset, const MappedModel& body);

glm::vec3 origin(const glm::mat4& m);
// Rotation of a matrix with uniform scale.
glm::quat rotation_of(const glm::mat4& m);

// Every node at rest, every morph weight 0.
void reset_pose(const model::ModelAsset& asset, model::ModelPose& pose);
// Turns `node` (if any) by `radians` about its local `axis`.
void turn(model::ModelPose& pose, int node, float radians, const glm::vec3& axis);
// Moves `node` (if any) by `delta` in its parent's frame (the character's, on these rigs).
void move(model::ModelPose& pose, int node, const glm::vec3& delta);
// Sets morph `index` (if any) to `value` clamped to [0, 1].
void set_morph(model::ModelPose& pose, int index, double value);

// A performer's place on the stage (components::Transform: mm, the scene's frame) from a scene's
// position (m) and facing (degrees about +Y).
components::Transform stage_transform(const scene::Vec3& position_m, double facing_deg);

// Seated legs on a 460 mm seat; with `breath`, the breathing chest (default rig axes).
void pose_body_base(const BodyNodes& n, bool seated, const model::ModelAsset& body,
                    const components::Breath* breath, model::ModelPose& pose);

// The ensemble's motion on the default rig (player facing +Z, their left +X, identity rest
// rotations): weight on one foot, knees, sway and twist from the spine, the breathing chest, the
// head's nod.
void pose_body_motion(const BodyNodes& n, bool seated, const model::ModelAsset& body,
                      const components::BodyMotion& m, model::ModelPose& pose);

}  // namespace tutti::stage
