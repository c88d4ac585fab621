// SPDX-License-Identifier: MIT
#pragma once
// The piano family's own components, on the pianist's performer entity: what was planned
// (PianistPlan: the editor pins fingers on its notes, a re-plan shares it when nothing it depends
// on changed) and how the plan drives the models (PianoRig: the pose system's bindings).

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <tutti/ecs/entity.hpp>
#include <tutti/finger_motion/finger_pose_system.hpp>
#include <tutti/fingering_planner/chord_roll.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/key_action/key_simulation.hpp>
#include <tutti/key_action/performance_report.hpp>
#include <tutti/music/score.hpp>
#include <optional>
#include <tutti/piano/hand_capsules.hpp>
#include <tutti/piano/pedal_feet.hpp>

#include <tutti/stage/body_retarget.hpp>
#include <tutti/stage/performer_rig.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::piano {

struct PianistPlan {
  // What the pianist plays (their parts, pins applied) and the fingering planned for it: the
  // editor shows and pins fingers on these notes.
  music::Score score;
  fingering_planner::ScorePlan fingering;
  std::shared_ptr<const finger_motion::PianistMotion> motion;
  // `score.notes[i]` is the stage score's note full_index[i].
  std::vector<std::size_t> full_index;
  // Everything the plan depends on (parts, music, hand size, style, pins): a re-plan with the
  // same key shares the plan.
  std::string plan_key;
  // The fingering before the scene's pins (the file's own marks pinned) and what it depends on:
  // pins re-plan only the span around them from it.
  fingering_planner::ScorePlan base_fingering;
  std::string base_key;
  // Chords a hand cannot span, rolled (chord_roll.hpp): applied to `score`; planned with the
  // base fingering.
  fingering_planner::ChordRolls rolls;
  std::vector<std::string> plan_notes;
  // An organ's pedal notes and the feet that play them (pedal_feet.hpp); a press's `note` is
  // the stage score's note index. Empty without a pedalboard.
  std::shared_ptr<const FeetPlan> feet;
  // With a performance style (scene pianist "style" / "sound": "keys"): what the simulated keys
  // did with each note of `score` (systems/key_action), and its summary. Empty without a style.
  std::shared_ptr<const std::vector<key_action::PlayedNote>> played;
  key_action::PerformanceReport performance;
};

struct PianoRig {
  std::array<ecs::Entity, 2> hands{ecs::Entity::null, ecs::Entity::null};  // right, left
  std::array<std::array<ecs::Entity, 5>, 2> fingers{};
  ecs::Entity piano = ecs::Entity::null;                                     // PlacedModel
  std::array<ecs::Entity, 2> hand_models{ecs::Entity::null, ecs::Entity::null};  // right, left
  // With a user's character the hand models are posed here but not drawn: the character's own
  // hands put their fingertips where the hand models' are.
  std::array<stage::PlacedModel, 2> hand_targets;
  // The seated performer rig (when generated): arms reach the hand models' wrists; the rig's
  // own hands are folded away (scale 0) because the hand models draw them. A user's character
  // plays with its own hands, through its stand-in.
  ecs::Entity body = ecs::Entity::null;
  stage::BodyNodes body_nodes;  // of the model posed: tutti's performer, or the stand-in
  std::optional<stage::BodyRetarget> body_retarget;
  // A user's hand models (scene pianist "hands"): drawn, posed through their stand-in where
  // tutti's hand models play; `hands_nodes` index the stand-in.
  ecs::Entity user_hands = ecs::Entity::null;
  std::optional<stage::BodyRetarget> hands_retarget;
  stage::BodyNodes hands_nodes;
  std::array<int, 2> rig_hands{-1, -1};  // right, left
  std::array<int, 128> key_nodes{};      // piano node per MIDI key, -1 = none
  // An organ's pedals: node per MIDI key (-1 = none), and the feet's plan (null = no pedals).
  std::array<int, 128> pedal_nodes{};
  std::shared_ptr<const FeetPlan> feet;
  std::array<ecs::Entity, 2> foot_entities{ecs::Entity::null, ecs::Entity::null};  // right, left
  std::vector<glm::mat4> scratch_instrument_world;
  std::array<double, 128> key_dip_rad{};
  // How far behind the key node's origin (the visible key's back edge) its lever turns: the
  // balance rail, hidden under the fallboard (m, along the key's -Z).
  std::array<float, 128> key_pivot_behind_m{};
  glm::mat4 keyboard_to_world{1.0f};  // the piano's `keyboard` node (metres, glTF axes)
  // Bones of each hand model, [finger 0..4][segment 0..2]; -1 = missing.
  // The pianist's hand preset's size over the generated hand models' (made at hands.json's
  // default preset): the hand models are drawn at the size the fingers were planned for.
  float hand_scale = 1.0f;
  std::array<std::array<std::array<int, 3>, 5>, 2> finger_bones{};
  std::array<int, 2> hand_root{-1, -1};
  // Each hand model's fingertip nodes ([side][finger]; -1 = missing), and each key's top at rest
  // in the keyboard frame: height and its back edge's depth into the keys (mm).
  std::array<std::array<int, 5>, 2> finger_tips{};
  std::array<double, 128> key_top_z_mm{};
  std::array<double, 128> key_back_y_mm{};
  std::array<double, 128> key_centre_x_mm{};  // across the keys, keyboard frame
  // Each key's top outline about its node (mm): half its widest width, and its length from the
  // back edge (the node's origin) to the front. 0 for a key without a mesh.
  std::array<double, 128> key_half_width_mm{};
  std::array<double, 128> key_length_mm{};
  glm::mat4 world_to_keyboard{1.0f};
  std::vector<glm::mat4> scratch_world;  // reused every frame by the pose system
  std::vector<glm::mat4> scratch_target_world;
  // Reused every frame by the idle fingers' yield (hands_apart.hpp): each hand's posed
  // world matrices and capsules.
  std::array<std::vector<glm::mat4>, 2> scratch_hand_world;
  std::array<std::vector<HandCapsule>, 2> scratch_hand_capsules;
};

// Hand model `side`'s finger chains (hand_capsules.hpp): each finger's three bones and its tip.
inline FingerChains finger_chains(const PianoRig& rig, std::size_t side) {
  FingerChains chains{};
  for (std::size_t f = 0; f < 5; ++f) {
    for (std::size_t j = 0; j < 3; ++j) chains[f][j] = rig.finger_bones[side][f][j];
    chains[f][3] = rig.finger_tips[side][f];
  }
  return chains;
}

}  // namespace tutti::piano
