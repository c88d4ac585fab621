#pragma once
// The performer rig both families pose (content/generator's performer.glb, or a user's character
// through a mapping file): the nodes a family needs of it, and the pose steps they share — the
// seated legs, the breathing chest, the ensemble's body motion — plus small pose helpers.

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
  int morph_tension = -1, morph_open = -1;  // indices into the pose's morph_weights
  // Finger bones [left, right][thumb .. little][segment], for the grip curls.
  std::array<std::array<std::array<int, 3>, 5>, 2> fingers{};
  // Their tips' nodes [left, right][thumb .. little] (-1 when the rig has none).
  std::array<std::array<int, 5>, 2> fingertips{};
  bool mapped = false;  // a user's rig (mapping file): only IK and morphs, no canned bends
  // A user's rig: each node's parent at rest in the character's frame (metres, +Y up, facing
  // +Z; the mapping's correction applied), so body motion defined on tutti's axes turns and moves
  // its bones whatever their own axes, rest rotations and units. Empty for the generated rig,
  // whose local axes are the character's.
  std::vector<glm::mat3> parent_rest;
};

Result<BodyNodes> find_body_nodes(const model::ModelAsset& asset, const MappedModel& body);

glm::vec3 origin(const glm::mat4& m);
// Rotation of a matrix with uniform scale.
glm::quat rotation_of(const glm::mat4& m);

// Every node at rest, every morph weight 0.
void reset_pose(const model::ModelAsset& asset, model::ModelPose& pose);
// Turns `node` (if any) by `radians` about its local `axis`.
void turn(model::ModelPose& pose, int node, float radians, const glm::vec3& axis);
// Turns `node` by `radians` about `axis` of the character's frame (+X its left, +Y up, +Z its
// front): on the generated rig that is its local axis; on a user's rig it is carried into the
// bone's own frame (BodyNodes::parent_rest).
void turn_body(const BodyNodes& n, model::ModelPose& pose, int node, float radians,
               const glm::vec3& axis);
// Moves `node` by `delta` metres of the character's frame.
void move_body(const BodyNodes& n, model::ModelPose& pose, int node, const glm::vec3& delta);
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
