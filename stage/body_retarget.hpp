// SPDX-License-Identifier: MIT
#pragma once
// A user's character posed through a stand-in (retargeting by bone directions).
//
// The families pose tutti's conventions (content/generator/README.md): every rest rotation the
// identity, the arms in tutti's A-pose, the fingers along the hand's -Y with the index toward +Z,
// flexion about ±Z. A user's rig has its own rest rotations, T- or A-pose, finger axes, units and
// extra bones (twist, metacarpals, toes). So the families pose a *proxy*: one node per role the
// user's rig has, at the user's joints (metres, +Y up, facing +Z), each bone's offsets turned
// into tutti's rest directions by a rotation Q (the bone's main child onto tutti's: the elbow for
// the upper arm; for the hand the middle knuckle and the knuckles' line; a chain's twist carried
// down from its parent), rest rotations the identity. Fingertips, the mouth and the palms' centres
// it lacks are estimated from the skin.
//
// Every frame each user bone then takes its proxy bone's world rotation through the rest
// difference — user world rotation = proxy world rotation · Q⁻¹ · user rest world rotation — so
// the bone points where the proxy's points. The proxy's offsets being the user's turned by the
// same Q, every user joint lands exactly on its proxy joint: a fingertip the hold puts on a button
// is on it in the user's rig too, whatever its proportions.

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <tutti/core/result.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/stage/model_binding.hpp>
#include <tutti/stage/performer_rig.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::stage {

struct BodyRetarget {
  // The stand-in the families pose: nodes named by role ("hips" .. "little_3_r", "index_tip_l",
  // "mouth", "grip_l"), rest rotations the identity; its root is the seat's placement.
  PlacedModel proxy;
  std::vector<int> user_node;       // per proxy node: the user's node; -1 for estimated points
  std::vector<glm::quat> to_user;   // per proxy node: Q⁻¹ · the user's rest world rotation
  std::vector<int> proxy_node;      // per user node: the proxy node driving it; -1 for the rest
  std::vector<glm::mat4> scratch_proxy_world, scratch_user_world;

  // The user's node that proxy node `node` drives (-1 when none).
  int user_node_of(int node) const {
    return node >= 0 ? user_node[static_cast<std::size_t>(node)] : -1;
  }
};

// The proxy of `user` (bound by `mapped`: its roles and correction), tutti's conventions read
// from `tutti` (performer.glb at rest). Errors: a mapping naming a node the model lacks.
Result<BodyRetarget> make_body_retarget(const model::ModelAsset& user, const MappedModel& mapped,
                                        const model::ModelAsset& tutti, const glm::mat4& placement);

// Poses `user` as `retarget.proxy` is posed now: every role bone's world rotation, the root's
// position and any joint the proxy moved, the morph weights. Allocation-free after the first call.
void apply_body_retarget(BodyRetarget& retarget, PlacedModel& user);

// A performer's body placed on a seat: tutti's performer (`character` empty), or a user's model
// (a model file or a mapping file) with its proxy. `nodes` index the model the families pose: the
// performer's, or the proxy's; their morph indices are the rendered model's.
struct PlacedBody {
  ecs::Entity placed = ecs::Entity::null;
  BodyNodes nodes;
  std::optional<BodyRetarget> retarget;
};
Result<PlacedBody> place_body(StageBuilder& builder, const std::filesystem::path& character,
                              const glm::mat4& placement);

// What the families pose for `body` on entity `placed`: the proxy when there is one.
inline PlacedModel* posed_body(PlacedModel* placed, std::optional<BodyRetarget>& retarget) {
  return placed != nullptr && retarget ? &retarget->proxy : placed;
}
inline const PlacedModel* posed_body(const PlacedModel* placed,
                                     const std::optional<BodyRetarget>& retarget) {
  return placed != nullptr && retarget ? &retarget->proxy : placed;
}

}  // namespace tutti::stage
