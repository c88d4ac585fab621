// SPDX-License-Identifier: MIT
#include <tutti/piano/piano_plugin.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include <tutti/components/finger.hpp>
#include <tutti/components/hand.hpp>
#include <tutti/components/note.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/components/transform.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include <tutti/piano_model/keyboard_instruments.hpp>
#include <tutti/key_action/key_action_params.hpp>
#include <tutti/piano/plan_pianist.hpp>
#include <tutti/piano/pose_feet.hpp>
#include <tutti/piano/pose_piano.hpp>
#include <tutti/stage/model_binding.hpp>
#include <tutti/stage/body_retarget.hpp>
#include <tutti/stage/performer_rig.hpp>
#include <tutti/stage/touching.hpp>

namespace tutti::piano {
namespace {

// The pianist's notes on the stage: who plays them with which hand and finger, and, when the
// keys make the sound, what was heard (missed notes are silent).
void claim_notes(stage::StageBuilder& builder, std::size_t music_file, const PianistPlan& plan,
                 ecs::Entity pianist, bool sound_from_keys, int fixed_velocity) {
  ecs::World& world = builder.world();
  for (std::size_t i = 0; i < plan.full_index.size(); ++i) {
    auto* note = world.try_get<components::Note>(builder.note_entity(music_file, plan.full_index[i]));
    if (note == nullptr) continue;
    note->performer = pianist;
    if (i < plan.fingering.hands.size()) {
      note->hand = plan.fingering.hands[i] == music::Hand::left ? components::HandSide::left
                                                                 : components::HandSide::right;
    }
    if (i < plan.fingering.fingers.size()) note->finger = plan.fingering.fingers[i];
    if (!sound_from_keys) {
      // A rolled chord's notes are heard as struck; their sound keeps its written end (as if
      // pedalled) though the key goes up early.
      if (i < plan.score.notes.size()) {
        note->onset_s = std::max(note->onset_s, plan.score.notes[i].onset_s);
        note->offset_s = std::max(note->offset_s, note->onset_s);
      }
      continue;
    }
    if (!plan.played || i >= plan.played->size()) continue;
    const key_action::PlayedNote& p = (*plan.played)[i];
    if (p.outcome == key_action::KeyOutcome::not_played) continue;
    if (p.outcome != key_action::KeyOutcome::sounded) {
      note->silent = true;
      continue;
    }
    // As key_action::performed_score: nothing sounds before the music's time 0.
    note->onset_s = std::max(p.onset_s, 0.0);
    note->offset_s = std::max(note->onset_s, p.offset_s);
    note->velocity = p.velocity;
  }
  // The pedal notes sound as written (at the instrument's one velocity when the keys make the
  // sound and it has one), and stop early where a foot had to leave its pedal early.
  if (!plan.feet) return;
  for (const PedalPress& press : plan.feet->presses) {
    auto* note = world.try_get<components::Note>(builder.note_entity(music_file, press.note));
    if (note == nullptr) continue;
    note->performer = pianist;
    note->finger = 0;
    note->offset_s = std::max(note->onset_s, std::min(note->offset_s, press.up_s));
    if (sound_from_keys && fixed_velocity > 0) note->velocity = fixed_velocity;
  }
}

// How far key node `node` turns at the bed, about the key action's balance rail: the lever's
// dip at its front over its length from the rail.
double key_dip_rad(const model::ModelAsset& piano, int node, const key_action::KeyLever& lever) {
  if (piano.nodes[static_cast<std::size_t>(node)].mesh < 0) return 0.0;
  return lever.bed_angle_rad();
}

// The rail behind the visible key's back edge (the key node's origin, `-translation.z` into the
// keys in the keyboard frame), in metres; 0 when the model's key reaches past it.
float key_pivot_behind_m(const model::ModelAsset& piano, int node, const key_action::KeyLever& lever) {
  const double back_y_mm =
      -1000.0 * static_cast<double>(piano.nodes[static_cast<std::size_t>(node)].rest.translation.z);
  return static_cast<float>(std::max(0.0, lever.pivot_y_mm - back_y_mm) / 1000.0);
}

// A key's top outline about its node (mm): the key mesh's widest |x| and its furthest +z (the
// node sits at the top's back edge, the key running toward +z, the player).
struct KeyOutlineMm {
  double half_width = 0.0;
  double length = 0.0;
};
KeyOutlineMm key_outline_mm(const model::ModelAsset& piano, int node) {
  const model::Node& key = piano.nodes[static_cast<std::size_t>(node)];
  if (key.mesh < 0) return {};
  float x_max = 0.0f, z_max = 0.0f;
  for (const model::Primitive& primitive : piano.meshes[static_cast<std::size_t>(key.mesh)].primitives) {
    for (std::uint32_t v = 0; v < primitive.vertex_count; ++v) {
      const glm::vec3& p = piano.vertices[primitive.first_vertex + v].position;
      x_max = std::max(x_max, std::abs(p.x));
      z_max = std::max(z_max, p.z);
    }
  }
  return {1000.0 * static_cast<double>(x_max), 1000.0 * static_cast<double>(z_max)};
}

// Where the piano stands: the generated piano is made for a bench at KeyboardPlayer's default
// spot (the keys' front at z = 0, the bench 0.6 m in front); a bench elsewhere takes the piano
// with it. At the default spot the piano's root is exactly the identity.
glm::mat4 piano_root(const KeyboardPlayer& pianist) {
  const KeyboardPlayer defaults;
  if (pianist.position_m == defaults.position_m && pianist.facing_deg == defaults.facing_deg) {
    return glm::mat4(1.0f);
  }
  return stage::placement_matrix(pianist.position_m, pianist.facing_deg) *
         glm::inverse(stage::placement_matrix(defaults.position_m, defaults.facing_deg));
}

Status bind_piano(stage::StageBuilder& builder, const piano_model::KeyboardInstrument& instrument,
                  const piano_model::Keyboard& keyboard, const key_action::KeyAction& action,
                  bool draw_hands, const glm::mat4& root, PianoRig& rig) {
  auto piano_model = builder.generated_model(instrument.model);
  if (!piano_model) return piano_model.error();
  rig.piano = builder.place(*piano_model, root);
  const model::ModelAsset& piano = builder.model(*piano_model);
  rig.key_nodes.fill(-1);
  rig.key_dip_rad.fill(0.0);
  for (int key = 0; key < 128; ++key) {
    const int node = piano.find_node("key_" + std::to_string(key));
    rig.key_nodes[static_cast<std::size_t>(key)] = node;
    if (node < 0) continue;
    const bool black = keyboard.contains(key) && keyboard.is_black(key);
    rig.key_dip_rad[static_cast<std::size_t>(key)] = key_dip_rad(piano, node, action.lever(black));
    rig.key_pivot_behind_m[static_cast<std::size_t>(key)] =
        key_pivot_behind_m(piano, node, action.lever(black));
    const glm::vec3& rest = piano.nodes[static_cast<std::size_t>(node)].rest.translation;
    rig.key_top_z_mm[static_cast<std::size_t>(key)] = 1000.0 * static_cast<double>(rest.y);
    rig.key_back_y_mm[static_cast<std::size_t>(key)] = -1000.0 * static_cast<double>(rest.z);
    rig.key_centre_x_mm[static_cast<std::size_t>(key)] = 1000.0 * static_cast<double>(rest.x);
    const KeyOutlineMm outline = key_outline_mm(piano, node);
    rig.key_half_width_mm[static_cast<std::size_t>(key)] = outline.half_width;
    rig.key_length_mm[static_cast<std::size_t>(key)] = outline.length;
  }
  rig.pedal_nodes.fill(-1);
  if (instrument.pedalboard) {
    for (int key = instrument.pedalboard->lowest_key; key <= instrument.pedalboard->highest_key; ++key) {
      rig.pedal_nodes[static_cast<std::size_t>(key)] = piano.find_node("pedal_" + std::to_string(key));
    }
  }
  {
    std::vector<glm::mat4> world(piano.nodes.size());
    model::compute_world_matrices(piano, builder.placed(rig.piano).pose, root, world);
    const int keyboard_node = piano.find_node("keyboard");
    if (keyboard_node >= 0) rig.keyboard_to_world = world[static_cast<std::size_t>(keyboard_node)];
    rig.world_to_keyboard = glm::inverse(rig.keyboard_to_world);
  }
  const char* finger_names[5] = {"thumb", "index", "middle", "ring", "little"};
  for (int side = 0; side < 2; ++side) {
    auto hand_model = builder.generated_model(side == 0 ? "hand_right.glb" : "hand_left.glb");
    if (!hand_model) return hand_model.error();
    if (draw_hands) {
      rig.hand_models[static_cast<std::size_t>(side)] = builder.place(*hand_model, glm::mat4(1.0f));
    } else {
      stage::PlacedModel& target = rig.hand_targets[static_cast<std::size_t>(side)];
      target.model = *hand_model;
      target.asset = builder.shared_model(*hand_model);
      target.pose = model::rest_pose(*target.asset);
    }
    const model::ModelAsset& hand = builder.model(*hand_model);
    rig.hand_root[static_cast<std::size_t>(side)] = hand.roots.empty() ? -1 : hand.roots[0];
    for (int f = 0; f < 5; ++f) {
      rig.finger_tips[static_cast<std::size_t>(side)][static_cast<std::size_t>(f)] =
          hand.find_node(std::string(finger_names[f]) + "_tip" + (side == 0 ? "_r" : "_l"));
      for (int s = 0; s < 3; ++s) {
        rig.finger_bones[static_cast<std::size_t>(side)][static_cast<std::size_t>(f)]
                        [static_cast<std::size_t>(s)] = hand.find_node(
            std::string(finger_names[f]) + "_" + std::to_string(s + 1) + (side == 0 ? "_r" : "_l"));
      }
    }
  }
  return Status::success();
}

Status bind_pianist_body(stage::StageBuilder& builder, const KeyboardPlayer& pianist,
                         double seat_raise_m, PianoRig& rig) {
  auto chair_model = builder.generated_model("chair.glb");
  if (!chair_model) return chair_model.error();
  // The chair's front (+Z) toward the keys, like the pianist; on an organ's platform raised with
  // the console over its pedals.
  glm::mat4 bench = stage::placement_matrix(pianist.position_m, pianist.facing_deg);
  if (seat_raise_m > 0.0) {
    bench *= glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, static_cast<float>(seat_raise_m), 0.0f));
  }
  builder.place(*chair_model, bench);
  if (pianist.character_mapping.empty() && !builder.generated_model_exists("performer.glb")) {
    return Status::success();
  }
  auto body = stage::place_body(builder, pianist.character_mapping, bench);
  if (!body) return body.error();
  rig.body = body->placed;
  rig.body_nodes = body->nodes;
  rig.body_retarget = std::move(body->retarget);
  if (!rig.body_retarget) {
    rig.rig_hands = {rig.body_nodes.arm_right.end, rig.body_nodes.arm_left.end};
  }
  return Status::success();
}

// A user's hand models (scene pianist "hands"): placed, and their stand-in made.
Status bind_user_hands(stage::StageBuilder& builder, const KeyboardPlayer& pianist, PianoRig& rig) {
  if (pianist.hands_mapping.empty()) return Status::success();
  auto hands = stage::load_hands(builder, pianist.hands_mapping);
  if (!hands) return hands.error();
  rig.user_hands = builder.place(hands->model, hands->correction);
  auto tutti = builder.generated_model("performer.glb");
  if (!tutti) return tutti.error();
  auto retarget = stage::make_body_retarget(builder.model(hands->model), *hands,
                                            builder.model(*tutti), glm::mat4(1.0f));
  if (!retarget) return retarget.error();
  auto nodes = stage::find_body_nodes(*retarget->proxy.asset, stage::MappedModel{});
  if (!nodes) return nodes.error();
  rig.hands_nodes = *nodes;
  rig.hands_retarget = std::move(*retarget);
  return Status::success();
}

}  // namespace

void PianoPlugin::add_systems(ecs::Schedule& schedule) const {
  finger_motion::register_finger_motion(schedule);
  schedule.add(ecs::Phase::evaluate, kFeetSystemName, feet_system,
               ecs::access(ecs::Reads<PianoRig>{}, ecs::Writes<components::Foot>{}));
  schedule.add(ecs::Phase::pose, kPianoSkeletonSystemName, piano_skeleton_system,
               ecs::access(ecs::Reads<PianoRig, components::Hand, components::Finger,
                                      components::Foot>{},
                           ecs::WritesOwn<stage::PlacedModel, stage::Touching>{}));
}

Status PianoPlugin::build(stage::StageBuilder& builder) const {
  for (std::size_t i = 0; i < keyboard_players(builder.scene()).size(); ++i) {
    if (Status s = build_pianist(builder, i); !s) return s;
  }
  return Status::success();
}

Status PianoPlugin::build_pianist(stage::StageBuilder& builder, std::size_t index) const {
  const KeyboardPlayer& pianist = keyboard_players(builder.scene())[index];
  auto planned = plan_pianist(builder, index);
  if (!planned) return planned.error();
  PianistPlan& plan = *planned;
  for (const std::string& note : plan.plan_notes) builder.note(note);
  // The instrument, its keyboard and its key levers, for the keys' dip.
  auto instruments = piano_model::KeyboardInstruments::load(
      piano_model::keyboard_instruments_path(builder.content_dir()));
  if (!instruments) return instruments.error();
  const piano_model::KeyboardInstrument* instrument = instruments->find(pianist.instrument);
  if (instrument == nullptr) return Error{"no keyboard instrument \"" + pianist.instrument + "\""};
  auto model = fingering_planner::load_fingering_model("default", pianist.hand_size,
                                                       builder.content_dir(), instrument);
  if (!model) return model.error();
  auto action = key_action::load_key_action(
      key_action::key_action_path(builder.content_dir()), instrument->touch_or_piano(),
      "instruments.json /instruments/" + instrument->id + "/touch");
  if (!action) return action.error();

  ecs::World& world = builder.world();
  const ecs::Entity performer =
      builder.add_performer(name(), index, components::Performer{pianist.name, pianist.seed});
  world.get<stage::Seat>(performer).instrument = pianist.instrument;
  world.get<stage::Seat>(performer).player = pianist.pointer;
  claim_notes(builder, pianist.music_file, plan, performer, pianist.sound_from_keys,
              static_cast<int>(action->velocity.fixed));
  world.add<components::Transform>(
      performer, stage::stage_transform(pianist.position_m, pianist.facing_deg));
  world.add<finger_motion::PianistMotionHandle>(performer,
                                                finger_motion::PianistMotionHandle{plan.motion});
  PianoRig rig;
  // The generated hand models are made at hands.json's default preset (content/generator).
  auto default_hands =
      fingering_planner::load_fingering_model("default", "", builder.content_dir());
  if (!default_hands) return default_hands.error();
  rig.hand_scale = static_cast<float>(model->hand.scale() / default_hands->hand.scale());
  for (int side = 0; side < 2; ++side) {
    const auto hand_side = side == 0 ? components::HandSide::right : components::HandSide::left;
    const ecs::Entity hand = world.create();
    components::Hand hand_value;
    hand_value.side = hand_side;
    hand_value.performer = performer;
    world.add<components::Hand>(hand, hand_value);
    rig.hands[static_cast<std::size_t>(side)] = hand;
    for (int f = 0; f < 5; ++f) {
      const ecs::Entity finger = world.create();
      components::Finger finger_value;
      finger_value.hand = hand;
      finger_value.side = hand_side;
      finger_value.finger = f + 1;
      world.add<components::Finger>(finger, finger_value);
      rig.fingers[static_cast<std::size_t>(side)][static_cast<std::size_t>(f)] = finger;
    }
  }
  // tutti's hand models are drawn unless a user's hands play: a character's own, or hand models.
  const bool users_hands = !pianist.character_mapping.empty() || !pianist.hands_mapping.empty();
  if (Status s = bind_piano(builder, *instrument, model->keyboard, *action, !users_hands,
                                piano_root(pianist), rig); !s) return s;
  const double seat_raise_m =
      instrument->pedalboard ? instrument->pedalboard->seat_raise_mm / 1000.0 : 0.0;
  if (Status s = bind_pianist_body(builder, pianist, seat_raise_m, rig); !s) return s;
  if (Status s = bind_user_hands(builder, pianist, rig); !s) return s;
  // Export names: "piano" (see below), "<pianist> hand_r", "<pianist> hand_l", the pianist's body.
  const auto label = [&](ecs::Entity instance, std::string text, bool after_performer) {
    if (instance.is_null()) return;
    stage::PlacedModel& placed = builder.placed(instance);
    placed.performer = performer;
    placed.label = std::move(text);
    placed.after_performer = after_performer;
  };
  // The instruments: "piano", then "piano 2", "organ", ... (export node names are unique).
  const auto& pianists = keyboard_players(builder.scene());
  const auto same_before =
      std::count_if(pianists.begin(), pianists.begin() + static_cast<std::ptrdiff_t>(index),
                    [&](const KeyboardPlayer& p) { return p.instrument == pianist.instrument; });
  label(rig.piano,
        same_before == 0 ? instrument->id : instrument->id + " " + std::to_string(same_before + 1),
        false);
  label(rig.hand_models[0], "hand_r", true);
  label(rig.hand_models[1], "hand_l", true);
  label(rig.body, "", true);
  label(rig.user_hands, "hands", true);
  rig.feet = plan.feet;
  if (rig.feet) {
    for (int side : {kRightFoot, kLeftFoot}) {
      const ecs::Entity foot = world.create();
      components::Foot value;
      value.performer = performer;
      value.side = side == kRightFoot ? components::HandSide::right : components::HandSide::left;
      world.add<components::Foot>(foot, value);
      rig.foot_entities[static_cast<std::size_t>(side)] = foot;
    }
  }
  world.add<PianoRig>(performer, std::move(rig));
  world.add<stage::Touching>(performer, stage::Touching{});
  world.add<PianistPlan>(performer, std::move(plan));
  return Status::success();
}

}  // namespace tutti::piano
