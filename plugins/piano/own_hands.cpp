// SPDX-License-Identifier: MIT
#include <tutti/piano/own_hands.hpp>

#include <algorithm>
#include <cmath>

#include <tutti/components/finger.hpp>
#include <tutti/stage/stage.hpp>
#include <tutti/stage/two_bone_ik.hpp>

namespace tutti::piano {
namespace {

// A nominal curl for placing the wrist: a pianist's rounded hand.
stage::FingerCurls pianist_curls() {
  stage::FingerCurls curls;
  curls.finger = {glm::radians(20.0f), glm::radians(45.0f), glm::radians(20.0f)};
  curls.thumb = glm::radians(15.0f);
  return curls;
}

}  // namespace

glm::vec3 pianist_elbow_pole(const glm::mat4& root, int side) {
  glm::mat4 facing = root;
  facing[3] = glm::vec4(0, 0, 0, 1);
  const glm::vec3 left = glm::vec3(facing * glm::vec4(1, 0, 0, 0));
  const glm::vec3 back = glm::vec3(facing * glm::vec4(0, 0, -1, 0));
  return glm::vec3(0, -1, 0) + (side == 0 ? -0.7f : 0.7f) * left + 0.2f * back;
}

void pose_seated_pianist(const stage::BodyNodes& nodes, const model::ModelAsset& asset,
                         model::ModelPose& pose) {
  stage::reset_pose(asset, pose);
  stage::pose_body_base(nodes, true, asset, nullptr, pose);
  stage::turn(pose, nodes.chest, 0.12f, {1, 0, 0});  // leaning toward the keys
  stage::turn(pose, nodes.neck, 0.14f, {1, 0, 0});   // looking down at them
  stage::turn(pose, nodes.head, 0.14f, {1, 0, 0});
}

float ArmPlacer::place(const glm::vec3& wrist, const glm::quat& rotation,
                       std::vector<glm::mat4>& world) {
  world.resize(asset_.nodes.size());
  model::compute_world_matrices(asset_, pose_, root_, world);
  stage::solve_two_bone_ik(asset_, arm_, wrist, pianist_elbow_pole(root_, side_), root_, pose_,
                           world);
  const int forearm = asset_.nodes[static_cast<std::size_t>(arm_.end)].parent;
  const glm::quat parent_rotation =
      forearm >= 0 ? stage::rotation_of(world[static_cast<std::size_t>(forearm)])
                   : stage::rotation_of(root_);
  pose_.local[static_cast<std::size_t>(arm_.end)].rotation =
      glm::normalize(glm::inverse(parent_rotation) * rotation);
  model::compute_world_matrices(asset_, pose_, root_, world);
  return glm::distance(glm::vec3(world[static_cast<std::size_t>(arm_.end)][3]), wrist);
}

void ArmPlacer::refresh(std::vector<glm::mat4>& world) const {
  world.resize(asset_.nodes.size());
  model::compute_world_matrices(asset_, pose_, root_, world);
}

void FreeHandPlacer::refresh(std::vector<glm::mat4>& world) const {
  world.resize(asset_.nodes.size());
  model::compute_world_matrices(asset_, pose_, root_, world);
}

float FreeHandPlacer::place(const glm::vec3& wrist, const glm::quat& rotation,
                            std::vector<glm::mat4>& world) {
  world.resize(asset_.nodes.size());
  const auto hand = static_cast<std::size_t>(hand_);
  const int forearm = asset_.nodes[hand].parent;
  // In the root's frame (the stand-in's root is the stage's: no scale).
  const glm::mat4 into_root = glm::inverse(root_);
  const glm::quat turn = glm::normalize(stage::rotation_of(into_root) * rotation);
  const glm::vec3 at = glm::vec3(into_root * glm::vec4(wrist, 1.0f));
  if (forearm >= 0) {
    // The forearm straight behind the hand, turned as the hand.
    const glm::vec3 offset = pose_.local[hand].translation;
    pose_.local[static_cast<std::size_t>(forearm)].rotation = turn;
    pose_.local[static_cast<std::size_t>(forearm)].translation = at - turn * offset;
    pose_.local[hand].rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
  } else {
    pose_.local[hand].rotation = turn;
    pose_.local[hand].translation = at;
  }
  model::compute_world_matrices(asset_, pose_, root_, world);
  return glm::distance(glm::vec3(world[hand][3]), wrist);
}

HandGoal hand_goal(const model::ModelAsset& hands, const stage::BodyNodes& nodes, PianoRig& rig,
                   int side) {
  HandGoal out;
  const auto s = static_cast<std::size_t>(side);
  const stage::PlacedModel& target = rig.hand_targets[s];
  if (target.asset == nullptr) return out;
  std::vector<glm::mat4>& world = rig.scratch_target_world;
  world.resize(target.asset->nodes.size());
  model::compute_world_matrices(*target.asset, target.pose, target.root, world);
  // The hand model's nodes, found once when it was bound (piano_plugin.cpp).
  for (std::size_t f = 0; f < 5; ++f) {
    const int tip = rig.finger_tips[s][f];
    if (tip < 0) continue;
    out.tips.world[f] = glm::vec3(world[static_cast<std::size_t>(tip)][3]);
    out.tips.has[f] = true;
    const int dip = rig.finger_bones[s][f][2];
    if (dip < 0) continue;
    const glm::vec3 last_bone = out.tips.world[f] - glm::vec3(world[static_cast<std::size_t>(dip)][3]);
    if (glm::length(last_bone) < 1e-6f) continue;
    out.pads[f] = out.tips.world[f] - stage::kFingertipPadRadiusM[f] * glm::normalize(last_bone);
    out.has_pad[f] = true;
  }
  const glm::vec3 treble = glm::normalize(glm::vec3(rig.keyboard_to_world * glm::vec4(1, 0, 0, 0)));
  const glm::vec3 into = glm::normalize(glm::vec3(rig.keyboard_to_world * glm::vec4(0, 0, -1, 0)));
  const glm::vec3 up = glm::normalize(glm::cross(treble, into));
  const float tilt = glm::radians(10.0f);
  const glm::vec3 y = -(std::cos(tilt) * into - std::sin(tilt) * up);
  const glm::vec3 index_side = side == 0 ? -treble : treble;
  const glm::vec3 z = glm::normalize(index_side - glm::dot(index_side, y) * y);
  out.rotation = glm::normalize(glm::quat_cast(glm::mat3(glm::cross(y, z), y, z)));
  const int body_side = side == 0 ? 1 : 0;  // the piano's right hand is the rig's _r (side 1)
  out.wrist = stage::fingertip_wrist(hands, nodes, body_side, pianist_curls(), out.tips,
                                     out.rotation, 1.0f);
  out.valid = true;
  return out;
}

// Places hand `side` on `goal`: the wrist through `placer`, the fingers bent onto their goals as
// far as their joints allow. Each fingertip's goal is then set again so that its own pad's centre
// (along its own last bone, as bent) meets the hand model's, and the pressing fingers left off
// move the wrist toward their goals; the best of eight tries stays.
float place_hand(const ecs::World& ecs_world, const model::ModelAsset& asset,
                 model::ModelPose& pose, const stage::BodyNodes& nodes, PianoRig& rig, int side,
                 HandGoal& goal, WristPlacer& placer, std::vector<glm::mat4>& world) {
  const auto s = static_cast<std::size_t>(side);
  const int body_side = side == 0 ? 1 : 0;  // the piano's right hand is the rig's _r (side 1)
  const auto b = static_cast<std::size_t>(body_side);
  if (!goal.valid) return 0.0f;
  const stage::FingerCurls curls = pianist_curls();
  glm::vec3 wrist = goal.wrist;
  glm::vec3 best_wrist = wrist;
  float best = 1e9f;
  float wrist_short = 0.0f;
  constexpr int kTries = 8;
  for (int attempt = 0; attempt <= kTries; ++attempt) {
    const bool last = attempt == kTries;
    if (last) wrist = best_wrist;
    const float short_now = placer.place(wrist, goal.rotation, world);
    if (!last) wrist_short = short_now;
    if (!last && attempt > 0 && short_now > 0.002f) {
      // The arm does not reach where the fingers want the wrist: the best reached place stays
      // (the caller leans in and tries again).
      attempt = kTries - 1;
      continue;
    }
    if (last) {
      // A pressing fingertip whose goal is still beyond its straight finger (a span wider than
      // the hand's) comes in along the key's top, not down through it: its height over the key
      // stays.
      for (std::size_t f = 0; f < 5; ++f) {
        const auto* finger = ecs_world.try_get<components::Finger>(rig.fingers[s][f]);
        const auto& bones = nodes.fingers[b][f];
        const int tip = nodes.fingertips[b][f];
        if (finger == nullptr || finger->press_depth <= 0.0 || !goal.tips.has[f] || tip < 0 ||
            bones[0] < 0 || bones[1] < 0 || bones[2] < 0) {
          continue;
        }
        float straight = 0.0f;
        for (const int node : {bones[1], bones[2], tip}) {
          straight += glm::length(asset.nodes[static_cast<std::size_t>(node)].rest.translation);
        }
        const glm::vec3 mcp = glm::vec3(world[static_cast<std::size_t>(bones[0])][3]);
        const glm::vec3 d = goal.tips.world[f] - mcp;
        if (glm::length(d) <= straight + 0.001f) continue;
        const float reach = 0.995f * straight;
        // The pressed key's top tilts toward the player: its normal, the keyboard's up turned
        // as the key is (about the keyboard's x, stage::turn in pose_pianist).
        glm::vec3 up(0.0f, 1.0f, 0.0f);
        if (finger->key >= 0 && finger->key < 128) {
          const float dip = static_cast<float>(finger->press_depth *
                                               rig.key_dip_rad[static_cast<std::size_t>(finger->key)]);
          up = glm::normalize(glm::mat3(rig.keyboard_to_world) *
                              (glm::angleAxis(dip, glm::vec3(1, 0, 0)) * glm::vec3(0, 1, 0)));
        }
        const float height = glm::dot(d, up);
        const glm::vec3 across = d - height * up;
        const float room = std::sqrt(std::max(0.0f, reach * reach - height * height));
        if (glm::length(across) < 1e-6f) continue;
        goal.tips.world[f] = mcp + height * up + room * glm::normalize(across);
      }
    }
    // No limits: the pads must reach the keys, and check-pose measures the pianist's pads on the
    // keys rather than the joints.
    stage::pose_fingers(asset, nodes, body_side, curls, &goal.tips, nullptr, world, pose);
    if (last) break;
    placer.refresh(world);  // the fingers' new pose
    glm::vec3 worst(0.0f), mean_miss(0.0f);
    int pressing = 0;
    for (std::size_t f = 0; f < 5; ++f) {
      const int tip = nodes.fingertips[b][f];
      const int dip = nodes.fingers[b][f][2];
      if (tip < 0 || !goal.tips.has[f]) continue;
      const glm::vec3 at = glm::vec3(world[static_cast<std::size_t>(tip)][3]);
      const auto* finger = ecs_world.try_get<components::Finger>(rig.fingers[s][f]);
      // Only the fingers on keys move the hand: the others hover where they can.
      if (finger != nullptr && finger->press_depth > 0.0) {
        const glm::vec3 miss = goal.tips.world[f] - at;
        if (glm::length(miss) > glm::length(worst)) worst = miss;
        mean_miss += miss;
        ++pressing;
      }
      if (dip < 0 || !goal.has_pad[f]) continue;
      const glm::vec3 last_bone = at - glm::vec3(world[static_cast<std::size_t>(dip)][3]);
      if (glm::length(last_bone) < 1e-6f) continue;
      goal.tips.world[f] = goal.pads[f] + stage::kFingertipPadRadiusM[f] * glm::normalize(last_bone);
    }
    if (glm::length(worst) < best) {
      best = glm::length(worst);
      best_wrist = wrist;
    }
    // One finger off: the wrist goes all the way; several: by their mean, so a span wider than
    // the hand's is shared between its ends.
    wrist += pressing > 1 ? mean_miss / static_cast<float>(pressing) : worst;
  }
  return wrist_short;
}

void pose_pianist_with_own_hands(const ecs::World& ecs_world, stage::PlacedModel& body,
                                 PianoRig& rig) {
  const model::ModelAsset& asset = *body.asset;
  pose_seated_pianist(rig.body_nodes, asset, body.pose);
  std::vector<glm::mat4>& world = rig.scratch_world;
  world.resize(asset.nodes.size());
  model::compute_world_matrices(asset, body.pose, body.root, world);
  std::array<HandGoal, 2> goals{hand_goal(asset, rig.body_nodes, rig, 0),
                                hand_goal(asset, rig.body_nodes, rig, 1)};
  constexpr float kMaxLean = 0.44f, kMaxSideLean = 0.25f;
  constexpr int kLeanPasses = 6;
  float leaned = 0.0f, side_leaned = 0.0f;
  for (int pass = 0; pass <= kLeanPasses; ++pass) {
    std::array<float, 2> short_of{};  // right, left hand
    for (int side = 0; side < 2; ++side) {
      const stage::TwoBoneChain& arm = side == 0 ? rig.body_nodes.arm_right : rig.body_nodes.arm_left;
      if (arm.end < 0) continue;
      ArmPlacer placer(asset, body.pose, body.root, arm, side);
      short_of[static_cast<std::size_t>(side)] =
          place_hand(ecs_world, asset, body.pose, rig.body_nodes, rig, side,
                     goals[static_cast<std::size_t>(side)], placer, world);
    }
    const float worst = std::max(short_of[0], short_of[1]);
    const int spine = rig.body_nodes.spine;
    const int shoulder = rig.body_nodes.arm_right.upper;
    if (worst <= 0.002f || pass == kLeanPasses || spine < 0 || shoulder < 0) break;
    model::compute_world_matrices(asset, body.pose, body.root, world);
    const float lever = glm::distance(glm::vec3(world[static_cast<std::size_t>(spine)][3]),
                                      glm::vec3(world[static_cast<std::size_t>(shoulder)][3]));
    if (lever < 0.05f) break;
    if (leaned < kMaxLean) {
      const float lean = std::min(kMaxLean - leaned, 1.2f * worst / lever);
      leaned += lean;
      stage::turn(body.pose, spine, lean, {1, 0, 0});
      stage::turn(body.pose, rig.body_nodes.neck, -0.5f * lean, {1, 0, 0});  // eyes on the keys
    } else {
      // Leaning in is not enough: toward the far hand's side (the player's left is +X; a turn
      // about +Z by a negative angle leans that way).
      const float toward_left = short_of[1] > short_of[0] ? 1.0f : -1.0f;
      const float lean = std::min(kMaxSideLean - side_leaned, 1.2f * worst / lever);
      if (lean <= 1e-4f) break;
      side_leaned += lean;
      stage::turn(body.pose, spine, -toward_left * lean, {0, 0, 1});
      stage::turn(body.pose, rig.body_nodes.neck, 0.5f * toward_left * lean, {0, 0, 1});
    }
    model::compute_world_matrices(asset, body.pose, body.root, world);
  }
}

std::array<glm::vec3, 2> pose_user_hands(const ecs::World& ecs_world, stage::PlacedModel& hands,
                                         PianoRig& rig) {
  const model::ModelAsset& asset = *hands.asset;
  stage::reset_pose(asset, hands.pose);
  std::vector<glm::mat4>& world = rig.scratch_world;
  world.resize(asset.nodes.size());
  model::compute_world_matrices(asset, hands.pose, hands.root, world);
  std::array<glm::vec3, 2> wrists{};
  for (int side = 0; side < 2; ++side) {
    const int hand = side == 0 ? rig.hands_nodes.arm_right.end : rig.hands_nodes.arm_left.end;
    if (hand < 0) continue;
    HandGoal goal = hand_goal(asset, rig.hands_nodes, rig, side);
    FreeHandPlacer placer(asset, hands.pose, hands.root, hand);
    place_hand(ecs_world, asset, hands.pose, rig.hands_nodes, rig, side, goal, placer, world);
    model::compute_world_matrices(asset, hands.pose, hands.root, world);
    wrists[static_cast<std::size_t>(side)] = glm::vec3(world[static_cast<std::size_t>(hand)][3]);
  }
  return wrists;
}

}  // namespace tutti::piano
