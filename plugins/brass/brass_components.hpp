// SPDX-License-Identifier: MIT
#pragma once
// The brass family's own components, on each brass player's performer entity: what was planned
// (BrassPlan: shared by a re-plan when nothing it depends on changed) and how the plan drives the
// models (BrassRig: the pose system's bindings).

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <tutti/brass/hold.hpp>
#include <tutti/brass_model/brass_line.hpp>
#include <tutti/brass_model/instrument.hpp>
#include <tutti/brass_motion/brass_pose_system.hpp>
#include <tutti/ecs/entity.hpp>
#include <tutti/stage/body_retarget.hpp>
#include <tutti/stage/performer_rig.hpp>

namespace tutti::brass {

struct BrassPlan {
  // The lines point at their instrument: it lives as long as the plan.
  std::shared_ptr<const brass_model::Instrument> instrument;
  std::shared_ptr<const brass_model::BrassLine> line;
  std::shared_ptr<const brass_motion::BrassPlayerMotion> player;
  // What this player's plan was made from (instrument, part, voice, music, breath marks).
  std::string plan_key;
  std::vector<std::string> plan_notes;  // the planner's diagnostics for this player
};

struct BrassRig {
  ecs::Entity instrument = ecs::Entity::null;  // components::Instrument, Valve / Slide
  ecs::Entity horn = ecs::Entity::null;        // PlacedModel
  ecs::Entity body = ecs::Entity::null;        // PlacedModel; null until the rig is generated
  ecs::Entity stand = ecs::Entity::null;       // PlacedModel: the music stand; null without one
  bool trombone = false;
  bool seated = false;
  stage::BodyNodes body_nodes;  // of the model posed: tutti's performer, or the stand-in
  std::optional<stage::BodyRetarget> body_retarget;  // a user's character: its stand-in
  static constexpr std::size_t kMaxValves = 4;  // the models' pistons (valve_1 .. valve_4)
  std::array<int, kMaxValves> valves{-1, -1, -1, -1};
  std::array<double, kMaxValves> valve_travel_m{};
  // Rotary valves' caps (rotor_1 ..), turning a quarter about their local +Y as the valve goes
  // down (-1: none).
  std::array<int, kMaxValves> rotors{-1, -1, -1, -1};
  // Press and slide directions in the nodes' parent frames (tutti's −Y and −Z there; a user's
  // model may have other axes).
  std::array<glm::vec3, kMaxValves> valve_axis{glm::vec3(0, -1, 0), glm::vec3(0, -1, 0),
                                               glm::vec3(0, -1, 0), glm::vec3(0, -1, 0)};
  glm::vec3 slide_axis{0, 0, -1};
  glm::mat4 horn_correction{1.0f};  // a user's instrument into tutti's frame (mapping file)
  int slide = -1;
  int mouthpiece = -1, grip_left = -1, grip_right = -1;
  Hold hold;  // content/instruments/holds/<model>.json
  stage::FingerJointLimits finger_limits;  // content/generator/hand_rig.json
  // The player's phrases [first onset, last offset] (s), rests shorter than a few seconds inside:
  // the instrument is up for them (raised before, lowered after), down between them.
  std::vector<std::array<double, 2>> phrases;
  // The instrument's nodes under each fingertip [left, right][thumb .. little] (-1: none).
  std::array<std::array<int, 5>, 2> fingertip_on{};
  glm::mat4 placement{1.0f};  // feet on the floor, facing
  std::vector<glm::mat4> scratch_horn_world;  // reused every frame by the pose system
  std::vector<glm::mat4> scratch_body_world;
};

}  // namespace tutti::brass
