// SPDX-License-Identifier: MIT
#include <tutti/piano/pose_feet.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <tutti/piano_model/pedal_geometry.hpp>
#include <tutti/stage/performer_rig.hpp>
#include <tutti/stage/two_bone_ik.hpp>

namespace tutti::piano {
namespace {

using piano_model::PedalGeometry;

// The sole pitched toes-down, as an organist plays with the toe (the heel off the pedal).
constexpr float kToesDownRad = 0.35f;

struct Leg {
  int thigh = -1, shin = -1, foot = -1, toe = -1;
  float outward = 0.0f;  // the knee's side, in the player's frame (their left is +X)
};

Leg leg_of(const stage::BodyNodes& n, int foot) {
  return foot == kRightFoot ? Leg{n.thigh_right, n.shin_right, n.foot_right, n.toe_right, -1.0f}
                            : Leg{n.thigh_left, n.shin_left, n.foot_left, n.toe_left, 1.0f};
}

// Where a toe presses pedal `key` (world), from the instrument's posed world matrices.
glm::vec3 toe_point(const PianoRig& rig, const std::vector<glm::mat4>& instrument_world, int key) {
  const int node = key >= 0 && key < 128 ? rig.pedal_nodes[static_cast<std::size_t>(key)] : -1;
  if (node < 0) return glm::vec3(0.0f);
  const float along = static_cast<float>(
      piano_model::pedal_is_sharp(key) ? PedalGeometry::kSharpToe_m : PedalGeometry::kNaturalToe_m);
  return glm::vec3(instrument_world[static_cast<std::size_t>(node)] * glm::vec4(0.0f, 0.0f, along, 1.0f));
}

}  // namespace

void feet_system(ecs::World& world, const ecs::FrameTime& frame) {
  world.view<const PianoRig>().each([&world, &frame](ecs::Entity, const PianoRig& rig) {
    if (!rig.feet) return;
    for (int side : {kRightFoot, kLeftFoot}) {
      auto* foot = world.try_get<components::Foot>(rig.foot_entities[static_cast<std::size_t>(side)]);
      if (foot == nullptr) continue;
      const FootState state = evaluate_foot(*rig.feet, side, frame.t_s);
      foot->from_key = state.from_key;
      foot->to_key = state.to_key;
      foot->travel = state.travel;
      foot->press_depth = state.depth;
      foot->key = state.depth > 0.0 ? state.from_key : -1;
      foot->lift_m = state.lift_m;
    }
  });
}

const components::Foot* foot_of(const ecs::World& world, const PianoRig& rig, int side) {
  if (!rig.feet || (side != kRightFoot && side != kLeftFoot)) return nullptr;
  return world.try_get<components::Foot>(rig.foot_entities[static_cast<std::size_t>(side)]);
}

void dip_pedals(const ecs::World& world, const PianoRig& rig, model::ModelPose& instrument_pose) {
  for (int side : {kRightFoot, kLeftFoot}) {
    const components::Foot* foot = foot_of(world, rig, side);
    if (foot == nullptr || foot->key < 0 || foot->key >= 128) continue;
    const int node = rig.pedal_nodes[static_cast<std::size_t>(foot->key)];
    stage::turn(instrument_pose, node, static_cast<float>(foot->press_depth * PedalGeometry::kDownRad),
                {1.0f, 0.0f, 0.0f});
  }
}

void pose_feet_on_pedals(const ecs::World& ecs_world, PianoRig& rig,
                         const stage::PlacedModel& instrument, stage::PlacedModel& body) {
  if (!rig.feet || rig.feet->empty() || instrument.asset == nullptr || body.asset == nullptr) return;
  std::vector<glm::mat4>& instrument_world = rig.scratch_instrument_world;
  instrument_world.resize(instrument.asset->nodes.size());
  model::compute_world_matrices(*instrument.asset, instrument.pose, instrument.root, instrument_world);
  const model::ModelAsset& asset = *body.asset;
  std::vector<glm::mat4>& world = rig.scratch_world;
  world.resize(asset.nodes.size());
  model::compute_world_matrices(asset, body.pose, body.root, world);
  const glm::quat facing = stage::rotation_of(body.root);
  const float scale = glm::length(glm::vec3(body.root[0]));
  const glm::quat toes_down = glm::angleAxis(kToesDownRad, glm::vec3(1.0f, 0.0f, 0.0f));
  for (int side : {kRightFoot, kLeftFoot}) {
    const Leg leg = leg_of(rig.body_nodes, side);
    if (leg.thigh < 0 || leg.shin < 0 || leg.foot < 0 || leg.toe < 0) continue;
    const components::Foot* foot = foot_of(ecs_world, rig, side);
    if (foot == nullptr || foot->from_key < 0) continue;
    const glm::vec3 from = toe_point(rig, instrument_world, foot->from_key);
    const glm::vec3 to = toe_point(rig, instrument_world, foot->to_key);
    const glm::vec3 up = glm::vec3(instrument.root * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
    const glm::vec3 target = glm::mix(from, to, static_cast<float>(foot->travel)) +
                             static_cast<float>(foot->lift_m) * glm::normalize(up);
    // The foot points from its hip toward the pedal (toes out at the board's ends), pitched
    // toes-down; the ankle where the toe point, turned with the sole, lands on the target.
    const glm::vec3 hip = glm::vec3(world[static_cast<std::size_t>(leg.thigh)][3]);
    const glm::vec3 ahead = glm::inverse(facing) * (target - hip);
    const float yaw = std::atan2(ahead.x, std::max(ahead.z, 1e-3f));
    const glm::quat sole =
        facing * glm::angleAxis(yaw, glm::vec3(0.0f, 1.0f, 0.0f)) * toes_down;
    const glm::vec3 toe_in_foot = asset.nodes[static_cast<std::size_t>(leg.toe)].rest.translation;
    const glm::vec3 ankle = target - sole * (scale * toe_in_foot);
    const glm::vec3 knee_pole = facing * glm::vec3(0.2f * leg.outward, 0.5f, 1.0f);
    stage::solve_two_bone_ik(asset, {leg.thigh, leg.shin, leg.foot}, ankle, knee_pole, body.root,
                             body.pose, world);
    const glm::quat shin_turn = stage::rotation_of(world[static_cast<std::size_t>(leg.shin)]);
    body.pose.local[static_cast<std::size_t>(leg.foot)].rotation =
        glm::normalize(glm::inverse(shin_turn) * sole);
  }
}

void touch_pedals(const ecs::World& world, const PianoRig& rig, stage::Touching& touching) {
  if (rig.body.is_null()) return;
  for (int side : {kRightFoot, kLeftFoot}) {
    const components::Foot* foot = foot_of(world, rig, side);
    if (foot == nullptr || foot->key < 0 || foot->key >= 128) continue;
    const Leg leg = leg_of(rig.body_nodes, side);
    stage::Touch touch;
    touch.part = rig.piano;
    touch.part_node = rig.pedal_nodes[static_cast<std::size_t>(foot->key)];
    touch.midi = foot->key;
    touch.body = rig.body;
    touch.body_node = rig.body_retarget ? rig.body_retarget->user_node_of(leg.toe) : leg.toe;
    if (touch.body_node < 0 && rig.body_retarget) {
      touch.body_node = rig.body_retarget->user_node_of(leg.foot);
    }
    touching.add(touch);
  }
}

}  // namespace tutti::piano
