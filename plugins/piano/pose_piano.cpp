// SPDX-License-Identifier: MIT
#include <tutti/piano/pose_piano.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <tutti/components/finger.hpp>
#include <tutti/components/hand.hpp>
#include <tutti/piano/hands_apart.hpp>
#include <tutti/piano/pad_seater.hpp>
#include <tutti/piano/pose_feet.hpp>
#include <tutti/piano/own_hands.hpp>
#include <tutti/piano/piano_components.hpp>
#include <tutti/stage/body_retarget.hpp>
#include <tutti/stage/fingertip_reach.hpp>
#include <tutti/stage/performer_rig.hpp>
#include <tutti/stage/stage.hpp>
#include <tutti/stage/touching.hpp>

namespace tutti::piano {
namespace {

using stage::PlacedModel;

// Keyboard frame (mm; x along the keys, y into them, z up) → the piano's `keyboard` node frame
// (metres, glTF axes): (x, y, z) → (x, z, -y) / 1000.
glm::vec3 keyboard_point(double x_mm, double y_mm, double z_mm) {
  return {static_cast<float>(x_mm / 1000.0), static_cast<float>(z_mm / 1000.0),
          static_cast<float>(-y_mm / 1000.0)};
}

// Wrist of a hand model placed at its middle-finger knuckle (the Hand reference point): behind
// it by about a palm and a little higher, in the keyboard frame (mm).
constexpr double kWristBehindKnuckleMm = 85.0;
constexpr double kWristAboveKnuckleMm = 12.0;

void pose_pianist_body(PlacedModel& body, PianoRig& rig, const std::array<glm::vec3, 2>& wrists) {
  const model::ModelAsset& asset = *body.asset;
  pose_seated_pianist(rig.body_nodes, asset, body.pose);
  for (int side : {0, 1}) {
    const int hand = rig.rig_hands[static_cast<std::size_t>(side)];
    if (hand >= 0) body.pose.local[static_cast<std::size_t>(hand)].scale = glm::vec3(0.0f);
  }
  std::vector<glm::mat4>& world = rig.scratch_world;
  world.resize(asset.nodes.size());
  model::compute_world_matrices(asset, body.pose, body.root, world);
  stage::solve_two_bone_ik(asset, rig.body_nodes.arm_right, wrists[0], pianist_elbow_pole(body.root, 0),
                           body.root, body.pose, world);
  stage::solve_two_bone_ik(asset, rig.body_nodes.arm_left, wrists[1], pianist_elbow_pole(body.root, 1),
                           body.root, body.pose, world);
}


void seat_pads_on_keys(ecs::World& world, PianoRig& rig, std::size_t side, PlacedModel& hand_model,
                       const std::array<double, 128>& key_down, SeatedFingers& seated) {
  for (std::size_t f = 0; f < 5; ++f) {
    const auto* finger = world.try_get<components::Finger>(rig.fingers[side][f]);
    const auto& bones = rig.finger_bones[side][f];
    if (finger == nullptr || finger->key < 0 || finger->key > 127 || finger->press_depth <= 0.0 ||
        bones[0] < 0 || bones[2] < 0 || rig.finger_tips[side][f] < 0) {
      continue;
    }
    const auto key = static_cast<std::size_t>(finger->key);
    if (rig.key_nodes[key] < 0) continue;
    const double angle = key_down[key] * rig.key_dip_rad[key];
    PadSeater seater(rig, hand_model, *finger, side, f, angle);
    const PadSeat centred = seater.centre({});
    const glm::dvec2 off = seater.off_key_mm(seater.measure(centred));
    PadSeat seat = centred;
    if (std::abs(off.x) > 0.0 || std::abs(off.y) > 0.0) seat = seater.onto_key(centred);
    else seater.pose(centred);
    seated.on_key[side][f] = true;
    seated.seat[side][f] = seat;
    seated.key_angle[side][f] = angle;
  }
}

void pose_pianist(ecs::World& world, PianoRig& rig) {
  auto* piano = world.try_get<PlacedModel>(rig.piano);
  if (piano == nullptr) return;
  std::array<glm::vec3, 2> wrists{};
  std::array<double, 128> key_down{};
  stage::reset_pose(*piano->asset, piano->pose);
  for (int side = 0; side < 2; ++side) {
    const auto* hand = world.try_get<components::Hand>(rig.hands[static_cast<std::size_t>(side)]);
    auto* hand_model = rig.hand_models[static_cast<std::size_t>(side)].is_null()
                           ? &rig.hand_targets[static_cast<std::size_t>(side)]
                           : world.try_get<PlacedModel>(rig.hand_models[static_cast<std::size_t>(side)]);
    if (hand_model == nullptr || hand_model->asset == nullptr) continue;
    stage::reset_pose(*hand_model->asset, hand_model->pose);
    if (hand == nullptr) continue;
    hand_model->root =
        rig.keyboard_to_world *
        glm::translate(glm::mat4(1.0f), keyboard_point(hand->x_mm, hand->y_mm, hand->z_mm));
    // Only a preset other than the default's scales (the default's poses stay bit for bit).
    if (rig.hand_scale != 1.0f) {
      hand_model->root *= glm::scale(glm::mat4(1.0f), glm::vec3(rig.hand_scale));
    }
    const double wrist_scale = rig.hand_scale;
    wrists[static_cast<std::size_t>(side)] = glm::vec3(
        rig.keyboard_to_world *
        glm::vec4(keyboard_point(hand->x_mm, hand->y_mm - kWristBehindKnuckleMm * wrist_scale,
                                 hand->z_mm + kWristAboveKnuckleMm * wrist_scale),
                  1.0f));
    const float mirror = side == 0 ? 1.0f : -1.0f;
    for (std::size_t f = 0; f < 5; ++f) {
      const auto* finger =
          world.try_get<components::Finger>(rig.fingers[static_cast<std::size_t>(side)][f]);
      if (finger == nullptr) continue;
      const auto& bones = rig.finger_bones[static_cast<std::size_t>(side)][f];
      // The generator's posing contract (content/generator/README.md), set absolutely:
      // first bone R(+Y, -m spread) R(-X, flexion), then R(-X, ...) for the next two; the thumb's
      // three bones take abduction, MCP and IP flexion.
      const double flexion[3] = {f == 0 ? finger->abduction_rad : finger->mcp_flexion_rad,
                                 f == 0 ? finger->mcp_flexion_rad : finger->pip_flexion_rad,
                                 f == 0 ? finger->pip_flexion_rad : finger->dip_flexion_rad};
      for (std::size_t s = 0; s < 3; ++s) {
        if (bones[s] < 0) continue;
        glm::quat rotation = glm::angleAxis(static_cast<float>(flexion[s]), glm::vec3(-1, 0, 0));
        if (s == 0) {
          rotation =
              glm::angleAxis(-mirror * static_cast<float>(finger->spread_rad), glm::vec3(0, 1, 0)) *
              rotation;
        }
        hand_model->pose.local[static_cast<std::size_t>(bones[s])].rotation = rotation;
      }
      if (finger->key >= 0 && finger->key < 128) {
        double& down = key_down[static_cast<std::size_t>(finger->key)];
        down = std::max(down, finger->press_depth);
      }
    }
  }
  // Where a finger touches its key, its pad is seated on the key's top (pad_seater.hpp).
  SeatedFingers seated;
  for (int side = 0; side < 2; ++side) {
    auto* hand_model = rig.hand_models[static_cast<std::size_t>(side)].is_null()
                           ? &rig.hand_targets[static_cast<std::size_t>(side)]
                           : world.try_get<PlacedModel>(rig.hand_models[static_cast<std::size_t>(side)]);
    if (hand_model == nullptr || hand_model->asset == nullptr) continue;
    seat_pads_on_keys(world, rig, static_cast<std::size_t>(side), *hand_model, key_down, seated);
  }
  {
    std::array<PlacedModel*, 2> hand_models{};
    for (std::size_t side = 0; side < 2; ++side) {
      hand_models[side] = rig.hand_models[side].is_null() ? &rig.hand_targets[side]
                                                          : world.try_get<PlacedModel>(rig.hand_models[side]);
    }
    keep_hands_apart(world, rig, hand_models, seated);
  }
  // A key two fingers hold (one handing it to the other, or both hands) goes down once: as far
  // as the deeper of them holds it.
  for (std::size_t key = 0; key < key_down.size(); ++key) {
    const int node = rig.key_nodes[key];
    if (node < 0 || key_down[key] <= 0.0) continue;
    const auto angle = static_cast<float>(key_down[key] * rig.key_dip_rad[key]);
    stage::turn(piano->pose, node, angle, {1, 0, 0});
    // About the rail behind the visible key: the rail point (0, 0, -d) stays where it is, so the
    // key's back edge goes down with its front.
    const float d = rig.key_pivot_behind_m[key];
    if (d > 0.0f) stage::move(piano->pose, node, {0.0f, -d * std::sin(angle), d * (std::cos(angle) - 1.0f)});
  }
  dip_pedals(world, rig, piano->pose);

  // A user's hand models: placed where tutti's play; the body's arms reach their wrists.
  if (rig.hands_retarget) {
    if (auto* hands = world.try_get<PlacedModel>(rig.user_hands)) {
      wrists = pose_user_hands(world, rig.hands_retarget->proxy, rig);
      stage::apply_body_retarget(*rig.hands_retarget, *hands);
    }
  }
  auto* body = world.try_get<PlacedModel>(rig.body);
  if (body == nullptr) return;
  if (!rig.body_retarget) {
    pose_pianist_body(*body, rig, wrists);
    pose_feet_on_pedals(world, rig, *piano, *body);
    return;
  }
  if (rig.hands_retarget) {
    // A user's character with a user's hands: its arms reach them, its own hands folded away.
    pose_pianist_body(rig.body_retarget->proxy, rig, wrists);
    pose_feet_on_pedals(world, rig, *piano, rig.body_retarget->proxy);
    stage::apply_body_retarget(*rig.body_retarget, *body);
    for (const int hand : {rig.body_nodes.arm_right.end, rig.body_nodes.arm_left.end}) {
      const int own = rig.body_retarget->user_node_of(hand);
      if (own >= 0) body->pose.local[static_cast<std::size_t>(own)].scale = glm::vec3(0.0f);
    }
    return;
  }
  pose_pianist_with_own_hands(world, rig.body_retarget->proxy, rig);
  pose_feet_on_pedals(world, rig, *piano, rig.body_retarget->proxy);
  stage::apply_body_retarget(*rig.body_retarget, *body);
}

// Each finger on its key (press depth > 0: the key moves with it), from the model that draws the
// finger: tutti's hand model, a user's hand models, or a user's character's own hands.
void touch_keys(ecs::World& world, const PianoRig& rig, stage::Touching& touching) {
  touching.clear();
  for (std::size_t side = 0; side < 2; ++side) {
    const std::size_t body_side = side == 0 ? 1 : 0;  // BodyNodes: [left, right]
    for (std::size_t f = 0; f < 5; ++f) {
      const auto* finger = world.try_get<components::Finger>(rig.fingers[side][f]);
      if (finger == nullptr || finger->key < 0 || finger->key >= 128 || finger->press_depth <= 0.0) {
        continue;
      }
      stage::Touch touch;
      touch.part = rig.piano;
      touch.part_node = rig.key_nodes[static_cast<std::size_t>(finger->key)];
      touch.midi = finger->key;
      if (!rig.hand_models[side].is_null()) {
        touch.body = rig.hand_models[side];
        touch.body_node = rig.finger_tips[side][f];
      } else if (rig.hands_retarget) {
        touch.body = rig.user_hands;
        touch.body_node = rig.hands_retarget->user_node_of(rig.hands_nodes.fingertips[body_side][f]);
      } else if (rig.body_retarget) {
        touch.body = rig.body;
        touch.body_node = rig.body_retarget->user_node_of(rig.body_nodes.fingertips[body_side][f]);
      }
      touching.add(touch);
    }
  }
}

}  // namespace

void piano_skeleton_system(ecs::World& world, const ecs::FrameTime&) {
  world.view<PianoRig>().each([&world](ecs::Entity performer, PianoRig& rig) {
    pose_pianist(world, rig);
    if (auto* touching = world.try_get<stage::Touching>(performer)) {
      touch_keys(world, rig, *touching);
      touch_pedals(world, rig, *touching);
    }
  });
}

}  // namespace tutti::piano
