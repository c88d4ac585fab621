// SPDX-License-Identifier: MIT
#include <tutti/stage/body_retarget.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include <tutti/scene/asset_mapping.hpp>
#include <tutti/stage/stage_builder.hpp>
#include <tutti/stage/two_bone_ik.hpp>

namespace tutti::stage {
namespace {

constexpr const char* kFingers[5] = {"thumb", "index", "middle", "ring", "little"};
constexpr const char* kSides[2] = {"_l", "_r"};

std::string finger_role(std::size_t f, const char* joint, std::size_t side) {
  return std::string(kFingers[f]) + "_" + joint + kSides[side];
}

// The roles a bone points at, nearest first (tutti's hierarchy): its direction is toward the
// first of them the rig has.
std::vector<std::string> main_children(const std::string& role) {
  const auto sided = [&](const char* base) {
    return role.size() > 2 && role.compare(role.size() - 2, 2, "_l") == 0 ? std::string(base) + "_l"
                                                                         : std::string(base) + "_r";
  };
  if (role == "hips") return {"spine", "chest", "neck", "head"};
  if (role == "spine") return {"chest", "neck", "head"};
  if (role == "chest") return {"neck", "head"};
  if (role == "neck") return {"head"};
  if (role.rfind("shoulder_", 0) == 0) return {sided("upper_arm")};
  if (role.rfind("upper_arm_", 0) == 0) return {sided("forearm")};
  if (role.rfind("forearm_", 0) == 0) return {sided("hand")};
  if (role.rfind("hand_", 0) == 0) return {sided("middle_1"), sided("ring_1"), sided("index_1")};
  if (role.rfind("thigh_", 0) == 0) return {sided("shin"), sided("foot")};
  if (role.rfind("shin_", 0) == 0) return {sided("foot")};
  for (const char* finger : kFingers) {
    const std::string f(finger);
    if (role.rfind(f + "_1", 0) == 0) return {sided((f + "_2").c_str()), sided((f + "_3").c_str()), sided((f + "_tip").c_str())};
    if (role.rfind(f + "_2", 0) == 0) return {sided((f + "_3").c_str()), sided((f + "_tip").c_str())};
    if (role.rfind(f + "_3", 0) == 0) return {sided((f + "_tip").c_str())};
  }
  return {};
}

// A second direction fixing a bone's twist, as (from, to) roles: the line across the hips, the
// shoulders, the knuckles.
std::vector<std::pair<std::string, std::string>> lateral_of(const std::string& role) {
  if (role == "hips") return {{"thigh_r", "thigh_l"}, {"upper_arm_r", "upper_arm_l"}};
  if (role == "chest" || role == "spine") return {{"upper_arm_r", "upper_arm_l"}, {"shoulder_r", "shoulder_l"}};
  for (std::size_t side = 0; side < 2; ++side) {
    if (role == std::string("hand") + kSides[side]) {
      return {{finger_role(4, "1", side), finger_role(1, "1", side)},
              {finger_role(3, "1", side), finger_role(1, "1", side)}};
    }
  }
  return {};
}

// An orthonormal frame: y along `main`, z along `lateral` made square to it.
bool frame_of(const glm::vec3& main, const glm::vec3& lateral, glm::mat3& out) {
  if (glm::length(main) < 1e-7f) return false;
  const glm::vec3 y = glm::normalize(main);
  const glm::vec3 across = lateral - glm::dot(lateral, y) * y;
  if (glm::length(across) < 0.2f * glm::length(lateral) || glm::length(across) < 1e-7f) return false;
  const glm::vec3 z = glm::normalize(across);
  out = glm::mat3(glm::cross(y, z), y, z);
  return true;
}

struct RestPoint {
  glm::vec3 at{0.0f};
  int node = -1;  // the model's node whose vertices (or itself) these are
};

// Every vertex at rest in the character frame (`world`: the rest pose's world matrices with the
// correction applied), with the node it follows most.
std::vector<RestPoint> rest_vertices(const model::ModelAsset& asset,
                                     const std::vector<glm::mat4>& world) {
  std::vector<RestPoint> out;
  for (std::size_t n = 0; n < asset.nodes.size(); ++n) {
    const model::Node& node = asset.nodes[n];
    if (node.mesh < 0) continue;
    const model::Skin* skin =
        node.skin >= 0 ? &asset.skins[static_cast<std::size_t>(node.skin)] : nullptr;
    for (const model::Primitive& primitive : asset.meshes[static_cast<std::size_t>(node.mesh)].primitives) {
      for (std::uint32_t v = 0; v < primitive.vertex_count; ++v) {
        const model::Vertex& vertex = asset.vertices[primitive.first_vertex + v];
        RestPoint point;
        if (skin == nullptr) {
          point.at = glm::vec3(world[n] * glm::vec4(vertex.position, 1.0f));
          point.node = static_cast<int>(n);
        } else {
          glm::vec4 sum(0.0f);
          float best = 0.0f;
          for (int c = 0; c < 4; ++c) {
            const float w = vertex.weights[c];
            const std::size_t j = vertex.joints[c];
            if (w <= 0.0f || j >= skin->joints.size()) continue;
            const int joint = skin->joints[j];
            sum += w * (world[static_cast<std::size_t>(joint)] * skin->inverse_bind[j] *
                        glm::vec4(vertex.position, 1.0f));
            if (w > best) {
              best = w;
              point.node = joint;
            }
          }
          if (point.node < 0) continue;
          point.at = glm::vec3(sum);
        }
        out.push_back(point);
      }
    }
  }
  return out;
}

bool descends_from(const model::ModelAsset& asset, int node, int ancestor) {
  for (int n = node; n >= 0; n = asset.nodes[static_cast<std::size_t>(n)].parent) {
    if (n == ancestor) return true;
  }
  return false;
}

}  // namespace

Result<BodyRetarget> make_body_retarget(const model::ModelAsset& user, const MappedModel& mapped,
                                        const model::ModelAsset& tutti, const glm::mat4& placement) {
  std::vector<glm::mat4> user_world(user.nodes.size()), tutti_world(tutti.nodes.size());
  model::compute_world_matrices(user, model::rest_pose(user), mapped.correction, user_world);
  model::compute_world_matrices(tutti, model::rest_pose(tutti), glm::mat4(1.0f), tutti_world);

  // The user's joints by role, and tutti's.
  std::map<std::string, int> node_of;  // role -> user node
  std::map<std::string, glm::vec3> at, tutti_at;
  for (const std::string_view role_view : scene::character_kind().node_roles) {
    const std::string role(role_view);
    auto node = find_role(user, mapped, role);
    if (!node) return node.error();
    if (*node >= 0) {
      node_of[role] = *node;
      at[role] = origin(user_world[static_cast<std::size_t>(*node)]);
    }
  }
  for (const model::Node& node : tutti.nodes) {
    const int n = tutti.find_node(node.name);
    tutti_at[node.name] = origin(tutti_world[static_cast<std::size_t>(n)]);
  }
  const auto has = [&](const std::string& role) { return at.count(role) > 0; };
  const auto tutti_has = [&](const std::string& role) { return tutti_at.count(role) > 0; };

  // Fingertips the rig lacks: the farthest flesh along the last bone (else an end bone under it,
  // else 0.8 of the bone before it). The user's body scale against tutti's, hips to head.
  const std::vector<RestPoint> flesh = rest_vertices(user, user_world);
  float scale = 1.0f;
  if (has("hips") && has("head") && tutti_has("hips") && tutti_has("head")) {
    scale = glm::distance(at["head"], at["hips"]) /
            std::max(1e-6f, glm::distance(tutti_at["head"], tutti_at["hips"]));
  }
  for (std::size_t side = 0; side < 2; ++side) {
    for (std::size_t f = 0; f < 5; ++f) {
      const std::string last = finger_role(f, "3", side), before = finger_role(f, "2", side);
      const std::string tip = finger_role(f, "tip", side);
      if (!has(last) || !has(before) || has(tip)) continue;
      const glm::vec3 dip = at[last];
      const float bone = glm::distance(dip, at[before]);
      if (bone < 1e-6f) continue;
      const glm::vec3 along = (dip - at[before]) / bone;
      const int distal = node_of[last];
      float reach = 0.0f;
      for (const RestPoint& p : flesh) {
        if (!descends_from(user, p.node, distal)) continue;
        const glm::vec3 d = p.at - dip;
        const float ahead = glm::dot(d, along);
        if (glm::length(d - ahead * along) < 0.02f * scale) reach = std::max(reach, ahead);
      }
      if (reach < 0.3f * bone) {
        const std::vector<int>& children = user.nodes[static_cast<std::size_t>(distal)].children;
        reach = children.empty()
                    ? 0.8f * bone
                    : std::max(0.3f * bone,
                               glm::dot(origin(user_world[static_cast<std::size_t>(children[0])]) - dip, along));
      }
      at[tip] = dip + reach * along;
    }
  }
  // The lips' front: tutti's mouth below the head joint, scaled, brought forward onto the face.
  if (!has("mouth") && has("head") && tutti_has("mouth") && tutti_has("head")) {
    glm::vec3 mouth = at["head"] + scale * (tutti_at["mouth"] - tutti_at["head"]);
    const int head = node_of["head"];
    const float window = 0.012f * scale;
    float front = -1e9f;
    for (const RestPoint& p : flesh) {
      if (!descends_from(user, p.node, head)) continue;
      if (std::abs(p.at.y - mouth.y) < window && std::abs(p.at.x - mouth.x) < window) {
        front = std::max(front, p.at.z);
      }
    }
    if (front > mouth.z - 0.08f * scale) mouth.z = front;
    at["mouth"] = mouth;
  }

  // The proxy's nodes: the user's role bones in the user's order (parents first), then the
  // estimated points under their bones.
  std::vector<std::string> order;
  for (const auto& [role, node] : node_of) order.push_back(role);
  std::sort(order.begin(), order.end(),
            [&](const std::string& a, const std::string& b) { return node_of[a] < node_of[b]; });
  std::map<std::string, int> parent_role_index;
  std::vector<std::string> parent_of(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    parent_role_index[order[i]] = static_cast<int>(i);
    for (int n = user.nodes[static_cast<std::size_t>(node_of[order[i]])].parent; n >= 0;
         n = user.nodes[static_cast<std::size_t>(n)].parent) {
      const auto found = std::find_if(node_of.begin(), node_of.end(),
                                      [&](const auto& entry) { return entry.second == n; });
      if (found != node_of.end()) {
        parent_of[i] = found->first;
        break;
      }
    }
  }
  const auto add_estimated = [&](const std::string& role, const std::string& parent) {
    if (node_of.count(role) == 0 && at.count(role) > 0 && node_of.count(parent) > 0) {
      order.push_back(role);
      parent_of.push_back(parent);
    }
  };
  for (std::size_t side = 0; side < 2; ++side) {
    for (std::size_t f = 0; f < 5; ++f) add_estimated(finger_role(f, "tip", side), finger_role(f, "3", side));
  }
  add_estimated("mouth", "head");

  // Q for each bone, parents first: the bone's main child (and, for hips, chest and hands, a
  // line across) turned from tutti's rest onto the user's; a bone without either keeps its
  // parent's.
  std::map<std::string, glm::quat> q;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::string& role = order[i];
    const glm::quat inherited = parent_of[i].empty() ? glm::quat(1, 0, 0, 0) : q[parent_of[i]];
    glm::quat turn = inherited;
    std::string child;
    for (const std::string& candidate : main_children(role)) {
      if (has(candidate) && tutti_has(candidate) && tutti_has(role)) {
        child = candidate;
        break;
      }
    }
    if (!child.empty()) {
      const glm::vec3 theirs = at[child] - at[role];
      const glm::vec3 ours = tutti_at[child] - tutti_at[role];
      bool framed = false;
      for (const auto& [from, to] : lateral_of(role)) {
        if (!has(from) || !has(to) || !tutti_has(from) || !tutti_has(to)) continue;
        glm::mat3 user_frame, tutti_frame;
        if (frame_of(theirs, at[to] - at[from], user_frame) &&
            frame_of(ours, tutti_at[to] - tutti_at[from], tutti_frame)) {
          turn = glm::normalize(glm::quat_cast(user_frame * glm::transpose(tutti_frame)));
          framed = true;
          break;
        }
      }
      if (!framed && glm::length(theirs) > 1e-7f && glm::length(ours) > 1e-7f) {
        turn = glm::normalize(
            rotation_between(glm::normalize(inherited * ours), glm::normalize(theirs)) * inherited);
      }
    }
    q[role] = turn;
  }
  // The palms' centres: tutti's, scaled by the hand's length, in the hand's turned frame.
  for (std::size_t side = 0; side < 2; ++side) {
    const std::string hand = std::string("hand") + kSides[side];
    const std::string grip = std::string("grip") + kSides[side];
    const std::string knuckle = finger_role(2, "1", side);
    if (has(grip) || !has(hand) || !tutti_has(grip) || !tutti_has(hand)) continue;
    float ratio = scale;
    if (has(knuckle) && tutti_has(knuckle)) {
      ratio = glm::distance(at[knuckle], at[hand]) /
              std::max(1e-6f, glm::distance(tutti_at[knuckle], tutti_at[hand]));
    }
    at[grip] = at[hand] + q[hand] * (ratio * (tutti_at[grip] - tutti_at[hand]));
    order.push_back(grip);
    parent_of.push_back(hand);
    q[grip] = q[hand];
  }

  BodyRetarget out;
  auto proxy = std::make_shared<model::ModelAsset>();
  proxy->source = user.source + " (tutti's stand-in)";
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const std::string& role = order[i];
    model::Node node;
    node.name = role;
    if (!parent_of[i].empty()) {
      node.parent = index.at(parent_of[i]);
      node.rest.translation = glm::inverse(q[parent_of[i]]) * (at[role] - at[parent_of[i]]);
      proxy->nodes[static_cast<std::size_t>(node.parent)].children.push_back(static_cast<int>(i));
    } else {
      node.rest.translation = at[role];
      proxy->roots.push_back(static_cast<int>(i));
    }
    // Attach points keep tutti's turn in their bone's frame: a grip's rotation is the hand's
    // frame as the holds define it (content/generator/README.md).
    if (role == "mouth" || role.rfind("grip_", 0) == 0) {
      const int own = tutti.find_node(role);
      if (own >= 0) node.rest.rotation = tutti.nodes[static_cast<std::size_t>(own)].rest.rotation;
    }
    index[role] = static_cast<int>(i);
    proxy->nodes.push_back(std::move(node));
    const auto user_node = node_of.find(role);
    out.user_node.push_back(user_node == node_of.end() ? -1 : user_node->second);
    if (!q.count(role)) q[role] = parent_of[i].empty() ? glm::quat(1, 0, 0, 0) : q[parent_of[i]];
    out.to_user.push_back(
        user_node == node_of.end()
            ? glm::quat(1, 0, 0, 0)
            : glm::normalize(glm::inverse(proxy->nodes.back().rest.rotation) * glm::inverse(q[role]) *
                             rotation_of(user_world[static_cast<std::size_t>(user_node->second)])));
  }
  out.proxy_node.assign(user.nodes.size(), -1);
  for (std::size_t i = 0; i < out.user_node.size(); ++i) {
    if (out.user_node[i] >= 0) out.proxy_node[static_cast<std::size_t>(out.user_node[i])] = static_cast<int>(i);
  }
  out.proxy.pose = model::rest_pose(*proxy);
  out.proxy.pose.morph_weights.assign(user.morph_weight_count(), 0.0f);
  out.proxy.asset = std::move(proxy);
  out.proxy.root = placement;
  return out;
}

void apply_body_retarget(BodyRetarget& retarget, PlacedModel& user) {
  const model::ModelAsset& proxy = *retarget.proxy.asset;
  const model::ModelAsset& asset = *user.asset;
  retarget.scratch_proxy_world.resize(proxy.nodes.size());
  retarget.scratch_user_world.resize(asset.nodes.size());
  model::compute_world_matrices(proxy, retarget.proxy.pose, retarget.proxy.root,
                                retarget.scratch_proxy_world);
  const std::vector<glm::mat4>& driven = retarget.scratch_proxy_world;
  std::vector<glm::mat4>& world = retarget.scratch_user_world;
  for (std::size_t n = 0; n < asset.nodes.size(); ++n) {
    const model::Node& node = asset.nodes[n];
    model::NodeTransform local = node.rest;
    const glm::mat4& parent =
        node.parent >= 0 ? world[static_cast<std::size_t>(node.parent)] : user.root;
    const int b = retarget.proxy_node[n];
    if (b >= 0) {
      const auto i = static_cast<std::size_t>(b);
      const glm::mat4& goal = driven[i];
      local.rotation =
          glm::normalize(glm::inverse(rotation_of(parent)) * rotation_of(goal) * retarget.to_user[i]);
      // The root of the roles, and any joint the families moved, go where the proxy's are.
      const model::Node& stand_in = proxy.nodes[i];
      if (stand_in.parent < 0 || retarget.proxy.pose.local[i].translation != stand_in.rest.translation) {
        local.translation = glm::vec3(glm::inverse(parent) * glm::vec4(origin(goal), 1.0f));
      }
    }
    user.pose.local[n] = local;
    world[n] = parent * model::to_matrix(local);
  }
  std::copy(retarget.proxy.pose.morph_weights.begin(), retarget.proxy.pose.morph_weights.end(),
            user.pose.morph_weights.begin());
}

Result<PlacedBody> place_body(StageBuilder& builder, const std::filesystem::path& character,
                              const glm::mat4& placement) {
  auto body = load_mapped(builder, character, "performer.glb");
  if (!body) return body.error();
  PlacedBody out;
  out.placed = builder.place(body->model, placement * body->correction);
  const model::ModelAsset& asset = builder.model(body->model);
  if (!body->mapping) {
    auto nodes = find_body_nodes(asset, *body);
    if (!nodes) return nodes.error();
    out.nodes = *nodes;
    return out;
  }
  auto tutti = builder.generated_model("performer.glb");
  if (!tutti) return tutti.error();
  auto retarget = make_body_retarget(asset, *body, builder.model(*tutti), placement);
  if (!retarget) return retarget.error();
  auto nodes = find_body_nodes(*retarget->proxy.asset, MappedModel{});
  if (!nodes) return nodes.error();
  out.nodes = *nodes;
  out.nodes.morph_tension = morph_index(asset, body->morph_name("tension"));
  out.nodes.morph_open = morph_index(asset, body->morph_name("open"));
  out.retarget = std::move(*retarget);
  return out;
}

}  // namespace tutti::stage
