#include <tutti/brass/pose_brass.hpp>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include <tutti/brass/brass_components.hpp>
#include <tutti/components/body_motion.hpp>
#include <tutti/components/breath.hpp>
#include <tutti/components/mouth.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/valve.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::brass_family {
namespace {

using stage::origin;
using stage::PlacedModel;

constexpr float kPi = 3.14159265f;

void pose_player(ecs::World& world, ecs::Entity performer, BrassRig& rig) {
  auto* horn = world.try_get<PlacedModel>(rig.horn);
  if (horn == nullptr) return;
  const model::ModelAsset& horn_asset = *horn->asset;
  stage::reset_pose(horn_asset, horn->pose);
  if (const auto* valve = world.try_get<components::Valve>(rig.instrument)) {
    for (std::size_t v = 0; v < 3; ++v) {
      if (rig.valves[v] < 0) continue;
      horn->pose.local[static_cast<std::size_t>(rig.valves[v])].translation +=
          rig.valve_axis[v] * static_cast<float>(valve->press[v] * rig.valve_travel_m[v]);
    }
  }
  if (const auto* slide = world.try_get<components::Slide>(rig.instrument);
      slide != nullptr && rig.slide >= 0) {
    horn->pose.local[static_cast<std::size_t>(rig.slide)].translation +=
        rig.slide_axis * static_cast<float>(slide->extension_mm / 1000.0);
  }

  std::vector<glm::mat4>& horn_world = rig.scratch_horn_world;
  horn_world.resize(horn_asset.nodes.size());
  model::compute_world_matrices(horn_asset, horn->pose, rig.horn_correction, horn_world);
  const glm::vec3 mouthpiece = rig.mouthpiece >= 0
                                   ? origin(horn_world[static_cast<std::size_t>(rig.mouthpiece)])
                                   : glm::vec3(0.0f);
  glm::mat4 facing = rig.placement;
  facing[3] = glm::vec4(0, 0, 0, 1);
  // Lips of a 1.75 m player, or the rig's mouth node.
  glm::vec3 lips = origin(rig.placement) + glm::vec3(facing * glm::vec4(0, 1.58f, 0.1f, 0));
  PlacedModel* body = world.try_get<PlacedModel>(rig.body);
  const components::BodyMotion* body_motion = nullptr;
  std::vector<glm::mat4>& body_world = rig.scratch_body_world;
  if (body != nullptr) {
    const model::ModelAsset& body_asset = *body->asset;
    stage::reset_pose(body_asset, body->pose);
    const auto* mouth = world.try_get<components::Mouth>(performer);
    const auto* breath = world.try_get<components::Breath>(performer);
    body_motion = world.try_get<components::BodyMotion>(performer);
    // With ensemble motion the breathing body comes from it (per-player depth); without, from
    // the Breath component alone.
    stage::pose_body_base(rig.body_nodes, rig.seated && !rig.body_nodes.mapped, body_asset,
                          body_motion != nullptr ? nullptr : breath, body->pose);
    if (body_motion != nullptr && !rig.body_nodes.mapped) {
      stage::pose_body_motion(rig.body_nodes, rig.seated, body_asset, *body_motion, body->pose);
    }
    if (mouth != nullptr) {
      // A phrase that outlasts the air strains the face; with ensemble motion, as the player's
      // expression shapes it (BodyMotion::strain starts from Breath::strain).
      const double strain = body_motion != nullptr ? 0.8 * body_motion->strain
                            : breath != nullptr    ? 0.8 * breath->strain
                                                   : 0.0;
      stage::set_morph(body->pose, rig.body_nodes.morph_tension, std::max(mouth->tension, strain));
      stage::set_morph(body->pose, rig.body_nodes.morph_open, mouth->open);
    }
    body_world.resize(body_asset.nodes.size());
    model::compute_world_matrices(body_asset, body->pose, body->root, body_world);
    if (rig.body_nodes.mouth >= 0) {
      lips = origin(body_world[static_cast<std::size_t>(rig.body_nodes.mouth)]);
    }
  }
  // The instrument hangs from the lips: its mouthpiece at the mouth, pointing where the player
  // faces, the bell a little down. The generated instruments point their bell along -Z (their
  // player at +Z); performers face +Z.
  const float tilt = (rig.trombone ? -0.08f : -0.16f) +
                     (body_motion != nullptr ? body_motion->bell_lift_rad : 0.0f);
  horn->root = glm::translate(glm::mat4(1.0f), lips) * facing *
               glm::rotate(glm::mat4(1.0f), kPi, glm::vec3(0, 1, 0)) *
               glm::rotate(glm::mat4(1.0f), tilt, glm::vec3(1, 0, 0)) *
               glm::translate(glm::mat4(1.0f), -mouthpiece) * rig.horn_correction;
  if (body == nullptr) return;

  // Fingers: the left hand wraps the valve casing or the bell brace, the right hand's fingertips
  // rest on the buttons / hold the slide brace. The default rig flexes its (hanging) fingers
  // about local -Z on the left, +Z on the right (content/generator/README.md).
  if (!rig.body_nodes.mapped) {
    constexpr float kDeg = kPi / 180.0f;
    const float left_curl[3] = {55 * kDeg, 45 * kDeg, 30 * kDeg};
    const float right_curl[3] = {30 * kDeg, 35 * kDeg, 20 * kDeg};
    for (std::size_t side = 0; side < 2; ++side) {
      const float* curl = side == 0 ? left_curl : right_curl;
      const glm::vec3 axis = side == 0 ? glm::vec3(0, 0, -1) : glm::vec3(0, 0, 1);
      for (std::size_t f = 1; f < 5; ++f) {
        for (std::size_t s = 0; s < 3; ++s) {
          stage::turn(body->pose, rig.body_nodes.fingers[side][f][s], curl[s], axis);
        }
      }
      stage::turn(body->pose, rig.body_nodes.fingers[side][0][1], 0.5f * curl[0], axis);
    }
  }

  // Hands on the grips: the hand turned so the rig's grip frame matches the instrument's, the
  // arm solved so the wrist lands where that puts the palm on the grip. The elbows hang down and
  // out to the player's sides (their left is +X when facing +Z).
  const model::ModelAsset& body_asset = *body->asset;
  const glm::vec3 left = glm::vec3(facing * glm::vec4(1, 0, 0, 0));
  const glm::vec3 back = glm::vec3(facing * glm::vec4(0, 0, -1, 0));
  const glm::vec3 down(0, -1, 0);
  const float body_scale = glm::length(glm::vec3(body->root[0]));
  for (int hand = 0; hand < 2; ++hand) {
    const int grip = hand == 0 ? rig.grip_left : rig.grip_right;
    if (grip < 0) continue;
    const stage::TwoBoneChain& arm = hand == 0 ? rig.body_nodes.arm_left : rig.body_nodes.arm_right;
    const int rig_grip = hand == 0 ? rig.body_nodes.grip_left : rig.body_nodes.grip_right;
    const glm::mat4 grip_world =
        horn->root * glm::inverse(rig.horn_correction) * horn_world[static_cast<std::size_t>(grip)];
    const glm::vec3 grip_position(grip_world[3]);
    const glm::vec3 pole = down + (hand == 0 ? left : -left) * 0.8f + back * 0.3f;
    if (rig_grip < 0 || arm.end < 0) {
      stage::solve_two_bone_ik(body_asset, arm, grip_position, pole, body->root, body->pose,
                               body_world);
      continue;
    }
    const model::NodeTransform& grip_rest =
        body_asset.nodes[static_cast<std::size_t>(rig_grip)].rest;
    const glm::quat hand_rotation =
        glm::normalize(stage::rotation_of(grip_world) * glm::inverse(grip_rest.rotation));
    const glm::vec3 wrist = grip_position - hand_rotation * (body_scale * grip_rest.translation);
    stage::solve_two_bone_ik(body_asset, arm, wrist, pole, body->root, body->pose, body_world);
    const int forearm = body_asset.nodes[static_cast<std::size_t>(arm.end)].parent;
    const glm::quat parent_rotation =
        forearm >= 0 ? stage::rotation_of(body_world[static_cast<std::size_t>(forearm)])
                     : stage::rotation_of(body->root);
    body->pose.local[static_cast<std::size_t>(arm.end)].rotation =
        glm::normalize(glm::inverse(parent_rotation) * hand_rotation);
    model::compute_world_matrices(body_asset, body->pose, body->root, body_world);
  }
}

}  // namespace

void brass_skeleton_system(ecs::World& world, const ecs::FrameTime&) {
  world.view<BrassRig>().each(
      [&world](ecs::Entity performer, BrassRig& rig) { pose_player(world, performer, rig); });
}

}  // namespace tutti::brass_family
