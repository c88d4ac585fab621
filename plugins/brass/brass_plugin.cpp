// SPDX-License-Identifier: MIT
#include <tutti/brass/brass_plugin.hpp>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include <tutti/brass/brass_components.hpp>
#include <tutti/brass/brass_players.hpp>
#include <tutti/brass/hold.hpp>
#include <tutti/brass/plan_brass_player.hpp>
#include <tutti/brass/pose_brass.hpp>
#include <tutti/components/body_motion.hpp>
#include <tutti/stage/body_retarget.hpp>
#include <tutti/components/breath.hpp>
#include <tutti/components/breath_schedule.hpp>
#include <tutti/components/instrument.hpp>
#include <tutti/components/mouth.hpp>
#include <tutti/components/note.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/transform.hpp>
#include <tutti/components/valve.hpp>
#include <tutti/ensemble_variation/ensemble_variation_system.hpp>
#include <tutti/stage/model_binding.hpp>
#include <tutti/stage/touching.hpp>

namespace tutti::brass {
namespace {

// A number from a node's glTF extras (the generated models' travel_mm), else the fallback: a user
// model without the node or the extra.
double extra_number(const model::ModelAsset& asset, int node, const char* key, double fallback) {
  if (node < 0 || static_cast<std::size_t>(node) >= asset.nodes.size()) return fallback;
  return asset.nodes[static_cast<std::size_t>(node)].number(key, fallback);
}

// The player's notes on the stage: who plays them, whether the instrument can, and the notes
// shortened to make room for a catch breath end early (the sound stops while the player breathes).
void claim_notes(stage::StageBuilder& builder, std::size_t music_file, const BrassPlan& plan,
                 ecs::Entity performer) {
  ecs::World& world = builder.world();
  for (const brass_model::LineNote& line_note : plan.line->notes) {
    if (line_note.score_index < 0) continue;
    auto* note = world.try_get<components::Note>(
        builder.note_entity(music_file, static_cast<std::size_t>(line_note.score_index)));
    if (note == nullptr) continue;
    note->performer = performer;
    note->playable = line_note.playable;
  }
  for (const brass_motion::ShortenedNote& shortened : plan.player->breaths.shortened) {
    if (shortened.note < 0 ||
        static_cast<std::size_t>(shortened.note) >= plan.line->notes.size()) {
      continue;
    }
    const int index = plan.line->notes[static_cast<std::size_t>(shortened.note)].score_index;
    if (index < 0) continue;
    auto* note = world.try_get<components::Note>(
        builder.note_entity(music_file, static_cast<std::size_t>(index)));
    if (note == nullptr) continue;
    note->offset_s = std::clamp(shortened.offset_s, note->onset_s, note->offset_s);
    note->offset_beats = std::clamp(shortened.offset_beats, note->onset_beats, note->offset_beats);
  }
}

// The player's phrases: playable notes joined across rests shorter than kLongRestS.
std::vector<std::array<double, 2>> phrases_of(const brass_model::BrassLine& line) {
  constexpr double kLongRestS = 4.0;
  std::vector<std::array<double, 2>> phrases;
  for (const brass_model::LineNote& note : line.notes) {
    if (!note.playable) continue;
    if (!phrases.empty() && note.onset_s - phrases.back()[1] < kLongRestS) {
      phrases.back()[1] = std::max(phrases.back()[1], note.offset_s);
    } else {
      phrases.push_back({note.onset_s, note.offset_s});
    }
  }
  return phrases;
}

// The instrument and, when there is one, the body of the player; their nodes; the stand and the
// chair.
Status bind_player(stage::StageBuilder& builder, const BrassPlayer& performer,
                   const std::string& model_stem, std::uint32_t stand_model,
                   std::uint32_t chair_model, bool rig_generated, BrassRig& rig) {
  auto horn = stage::load_mapped(builder, performer.instrument_mapping, model_stem + ".glb",
                                 kBrassAssetKinds);
  if (!horn) return horn.error();
  if (rig_generated || !performer.character_mapping.empty()) {
    auto body = stage::place_body(builder, performer.character_mapping, rig.placement);
    if (!body) return body.error();
    rig.body = body->placed;
    rig.body_nodes = body->nodes;
    rig.body_retarget = std::move(body->retarget);
  }
  rig.horn = builder.place(horn->model, rig.placement);
  rig.horn_correction = horn->correction;
  const model::ModelAsset& horn_asset = builder.model(horn->model);
  for (std::size_t v = 0; v < BrassRig::kMaxValves; ++v) {
    auto node = stage::find_role(horn_asset, *horn, "valve_" + std::to_string(v + 1));
    if (!node) return node.error();
    rig.valves[v] = *node;
    rig.valve_axis[v] = stage::local_axis(horn_asset, *node, horn->correction, {0, -1, 0});
    // A pad turned in its parent (the horn's thumb trigger) presses along its own -Y.
    if (*node >= 0 && !horn->mapping) {
      const glm::quat& turned = horn_asset.nodes[static_cast<std::size_t>(*node)].rest.rotation;
      if (std::abs(turned.w) < 0.9999f) rig.valve_axis[v] = turned * glm::vec3(0, -1, 0);
    }
    auto rotor = stage::find_role(horn_asset, *horn, "rotor_" + std::to_string(v + 1));
    if (!rotor) return rotor.error();
    rig.rotors[v] = *rotor;
    rig.valve_travel_m[v] = extra_number(horn_asset, *node, "travel_mm", 18.0) / 1000.0;
  }
  for (auto [slot, role] : {std::pair{&rig.slide, "slide"},
                            {&rig.mouthpiece, "mouthpiece"},
                            {&rig.grip_left, "grip_left"},
                            {&rig.grip_right, "grip_right"}}) {
    auto node = stage::find_role(horn_asset, *horn, role);
    if (!node) return node.error();
    *slot = *node;
  }
  rig.slide_axis = stage::local_axis(horn_asset, rig.slide, horn->correction, {0, 0, -1});
  auto hold = load_hold(builder.content_dir() / "instruments" / "holds" / (model_stem + ".json"));
  if (!hold) return hold.error();
  rig.hold = std::move(*hold);
  auto finger_limits = stage::load_finger_joint_limits(builder.content_dir());
  if (!finger_limits) return finger_limits.error();
  rig.finger_limits = *finger_limits;
  for (std::size_t side = 0; side < 2; ++side) {
    const HandHold& hand = rig.hold.hands[side];
    if (!hand.palm_at.empty()) {
      auto node = stage::find_role(horn_asset, *horn, hand.palm_at);
      if (!node) return node.error();
      (side == 0 ? rig.grip_left : rig.grip_right) = *node;
    }
    for (std::size_t f = 0; f < 5; ++f) {
      rig.fingertip_on[side][f] = -1;
      if (hand.fingertip_on[f].empty()) continue;
      auto node = stage::find_role(horn_asset, *horn, hand.fingertip_on[f]);
      if (!node) return node.error();
      rig.fingertip_on[side][f] = *node;
    }
  }
  if (performer.music_stand) {
    // The stand in front of the player (the hold's music_stand), desk toward them; the player's
    // left is +X (they face +Z).
    const glm::mat4 stand = glm::rotate(
        glm::translate(rig.placement, glm::vec3(rig.hold.stand_left_m, 0, rig.hold.stand_forward_m)),
                                        glm::radians(180.0f), glm::vec3(0, 1, 0));
    rig.stand = builder.place(stand_model, stand);
  }
  if (rig.seated) {
    builder.place(chair_model, glm::translate(rig.placement, glm::vec3(0, 0, -0.12f)));
  }
  return Status::success();
}

// The planned breaths as the editor and hosts read them.
components::BreathSchedule breath_schedule(const BrassPlan& plan) {
  components::BreathSchedule schedule;
  for (const brass_motion::BreathEvent& event : plan.player->breaths.events) {
    components::BreathSpan span;
    span.prepare_s = event.prepare_start_s;
    span.start_s = event.start_s;
    span.end_s = event.end_s;
    span.catch_breath = event.kind == brass_motion::BreathKind::catch_breath;
    span.marked = event.marked;
    span.boundary_s =
        event.before_note >= 0 &&
                static_cast<std::size_t>(event.before_note) < plan.line->notes.size()
            ? plan.line->notes[static_cast<std::size_t>(event.before_note)].onset_s
            : event.end_s;
    schedule.breaths.push_back(span);
  }
  return schedule;
}

ensemble_variation::PerformerInput ensemble_input(const BrassPlayer& performer,
                                                  const music::Score& score,
                                                  const BrassPlan& plan) {
  ensemble_variation::PerformerInput input;
  input.seed = performer.seed;
  input.params = ensemble_variation::resolve_variation(performer.seed, performer.variation);
  input.lead = performer.lead;
  input.score = &score;
  for (const brass_motion::BreathEvent& e : plan.player->breaths.events) {
    input.breaths.push_back({e.prepare_start_s, e.start_s, e.end_s, e.depth,
                             e.kind != brass_motion::BreathKind::catch_breath &&
                                 e.kind != brass_motion::BreathKind::before_entrance});
  }
  for (const scene::Expression& e : performer.expressions) {
    ensemble_variation::ExpressionSpan span;
    span.kind = e.kind == scene::ExpressionKind::strain ? ensemble_variation::ExpressionKind::strain
                                                        : ensemble_variation::ExpressionKind::relaxed;
    span.start_s = e.start_s;
    span.end_s = e.end_s;
    span.amount = e.amount;
    input.expressions.push_back(span);
  }
  if (!plan.player->motion.sounding.empty()) {
    input.first_onset_s = plan.player->motion.sounding.front().onset_s;
    input.last_offset_s = plan.player->motion.sounding.back().offset_s;
  }
  return input;
}

}  // namespace

void BrassPlugin::add_systems(ecs::Schedule& schedule) const {
  brass_motion::register_brass_motion(schedule);
  ensemble_variation::register_ensemble_variation(schedule);
  schedule.add(ecs::Phase::pose, kBrassSkeletonSystemName, brass_skeleton_system,
               ecs::access(ecs::Reads<BrassRig, components::Valve, components::Slide, components::Mouth,
                                      components::Breath, components::BodyMotion>{},
                           ecs::WritesOwn<stage::PlacedModel, stage::Touching>{}));
}

Status BrassPlugin::build(stage::StageBuilder& builder) const {
  const scene::Scene& scene = builder.scene();
  if (brass_players(scene).empty()) return Status::success();
  auto data = load_brass_planning_data(builder.content_dir());
  if (!data) return data.error();
  // The performer rig is not generated yet (content/generator/README.md): until it is, players
  // are their instruments at mouth height.
  const bool rig_generated = builder.generated_model_exists("performer.glb");
  auto stand_model = builder.generated_model("music_stand.glb");
  if (!stand_model) return stand_model.error();
  auto chair_model = builder.generated_model("chair.glb");
  if (!chair_model) return chair_model.error();

  ecs::World& world = builder.world();
  std::vector<ecs::Entity> players;
  std::vector<ensemble_variation::PerformerInput> ensemble_inputs;
  for (std::size_t seat = 0; seat < brass_players(scene).size(); ++seat) {
    const BrassPlayer& performer = brass_players(scene)[seat];
    auto planned = plan_brass_seat(builder, seat, *data);
    if (!planned) return planned.error();
    BrassPlan& plan = *planned;
    for (const std::string& note : plan.plan_notes) builder.note(note);
    const brass_model::Instrument& played = *plan.instrument;

    const ecs::Entity player = builder.add_performer(
        name(), seat, components::Performer{performer.name, performer.seed});
    world.get<stage::Seat>(player).instrument = played.id;
    world.get<stage::Seat>(player).player =
        "/" + std::string(kBrassPlayersKey) + "/" + std::to_string(seat);
    claim_notes(builder, performer.music_file, plan, player);
    world.add<components::Transform>(
        player, stage::stage_transform(performer.position_m, performer.facing_deg));
    world.add<brass_motion::BrassPlayerMotionHandle>(
        player, brass_motion::BrassPlayerMotionHandle{plan.player});
    world.add<components::Mouth>(player);
    world.add<components::Breath>(player);
    world.add<components::BreathSchedule>(player, breath_schedule(plan));
    BrassRig rig;
    rig.trombone = played.mechanism == brass_model::Mechanism::slide;
    rig.seated = performer.stance == scene::Stance::seated;
    rig.placement = stage::placement_matrix(performer.position_m, performer.facing_deg);
    rig.instrument = world.create();
    world.add<components::Instrument>(rig.instrument, components::Instrument{played.id, player});
    if (rig.trombone) {
      world.add<components::Slide>(rig.instrument);
    } else {
      components::Valve valve;
      valve.count = static_cast<std::uint8_t>(std::min<std::size_t>(played.valves.size(), 6));
      world.add<components::Valve>(rig.instrument, valve);
    }
    if (Status s = bind_player(builder, performer, played.model_name(), *stand_model,
                               *chair_model, rig_generated, rig);
        !s) {
      return s;
    }
    // Export names: the player's body by their name, the instrument "<name> <model file stem>".
    if (!rig.body.is_null()) {
      stage::PlacedModel& body = builder.placed(rig.body);
      body.performer = player;
      body.after_performer = true;
    }
    stage::PlacedModel& horn = builder.placed(rig.horn);
    horn.performer = player;
    horn.after_performer = true;
    horn.label = std::filesystem::path(builder.stage().model_files()[horn.model]).stem().string();

    ensemble_inputs.push_back(ensemble_input(performer, builder.scores()[performer.music_file], plan));
    rig.phrases = phrases_of(*plan.line);
    world.add<BrassRig>(player, std::move(rig));
    world.add<stage::Touching>(player, stage::Touching{});
    world.add<BrassPlan>(player, std::move(plan));
    players.push_back(player);
  }
  ensemble_variation::EnsembleOptions ensemble_options;
  ensemble_options.cues_s = scene.cues_s;
  auto ensemble_plan = ensemble_variation::plan_ensemble(ensemble_inputs, ensemble_options);
  builder.replanned("ensemble");
  if (!ensemble_plan) return ensemble_plan.error();
  const auto shared = std::make_shared<const ensemble_variation::EnsemblePlan>(std::move(*ensemble_plan));
  for (std::size_t i = 0; i < players.size(); ++i) {
    world.add<ensemble_variation::EnsembleMotionHandle>(players[i], ensemble_variation::EnsembleMotionHandle{shared, i});
    world.add<components::BodyMotion>(players[i]);
  }
  return Status::success();
}

}  // namespace tutti::brass
