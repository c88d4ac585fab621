#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>

#include <tutti/brass_model/instrument.hpp>
#include <tutti/brass_motion/brass_motion_params.hpp>
#include <tutti/brass_motion/brass_pose_system.hpp>
#include <tutti/brass_motion/breath_params.hpp>
#include <tutti/brass_motion/plan_brass_player.hpp>
#include <tutti/components/body_motion.hpp>
#include <tutti/components/breath.hpp>
#include <tutti/components/finger.hpp>
#include <tutti/components/hand.hpp>
#include <tutti/components/instrument.hpp>
#include <tutti/components/mouth.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/valve.hpp>
#include <tutti/content/content_dir.hpp>
#include <tutti/ensemble_variation/ensemble_variation_system.hpp>
#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/finger_motion/finger_pose_system.hpp>
#include <tutti/finger_motion/plan_finger_motion.hpp>
#include <tutti/fingering_planner/brass_lines.hpp>
#include <tutti/fingering_planner/brass_planner.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/key_action/humane_performance.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/piano_performance/performance_plan.hpp>
#include <tutti/scene/asset_mapping.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/stage/stage.hpp>

#ifndef TUTTI_DEFAULT_ASSET_DIR
#define TUTTI_DEFAULT_ASSET_DIR ""
#endif

namespace tutti::stage {
namespace {

glm::mat4 placement_matrix(const scene::Vec3& position, double facing_deg) {
  glm::mat4 m = glm::translate(
      glm::mat4(1.0f), glm::vec3(static_cast<float>(position.x), static_cast<float>(position.y),
                                 static_cast<float>(position.z)));
  return glm::rotate(m, glm::radians(static_cast<float>(facing_deg)), glm::vec3(0, 1, 0));
}

class ModelCache {
 public:
  ModelCache(Stage& stage, std::filesystem::path dir) : stage_(stage), dir_(std::move(dir)) {}

  // A generated asset, by file name in the asset folder.
  Result<std::uint32_t> get(const std::string& file) { return load(dir_ / file, true); }
  // A user's model (from a mapping file), by path.
  Result<std::uint32_t> get_user(const std::filesystem::path& path) { return load(path, false); }

  Result<std::uint32_t> load(const std::filesystem::path& path, bool generated) {
    const std::string file = path.string();
    for (std::size_t i = 0; i < stage_.model_files.size(); ++i) {
      if (stage_.model_files[i] == file) return static_cast<std::uint32_t>(i);
    }
    if (reuse_ != nullptr) {
      for (std::size_t i = 0; i < reuse_->model_files.size(); ++i) {
        if (reuse_->model_files[i] == file) return add(reuse_->models[i], file);
      }
    }
    Result<model::ModelAsset> loaded = model::load_model(path);
    if (!loaded) {
      if (!generated) return loaded.error();
      return Error{loaded.error().message +
                   " (the generated assets; build the tutti_content_assets target or set "
                   "TUTTI_ASSET_DIR)"};
    }
    return add(std::make_shared<const model::ModelAsset>(std::move(*loaded)), file);
  }

  void reuse(const Stage* previous) { reuse_ = previous; }
  const Stage* reused() const { return reuse_; }

  const std::filesystem::path& dir() const { return dir_; }

  std::size_t place(std::uint32_t model, const glm::mat4& root) {
    PlacedModel placed;
    placed.model = model;
    placed.root = root;
    placed.pose = model::rest_pose(*stage_.models[model]);
    stage_.placed.push_back(std::move(placed));
    return stage_.placed.size() - 1;
  }

 private:
  Stage& stage_;
  std::uint32_t add(std::shared_ptr<const model::ModelAsset> model, const std::string& file) {
    stage_.models.push_back(std::move(model));
    stage_.model_files.push_back(file);
    return static_cast<std::uint32_t>(stage_.models.size() - 1);
  }

  std::filesystem::path dir_;
  const Stage* reuse_ = nullptr;
};

// A model and how tutti finds its parts: the generated asset (roles are node names) or a user's
// model through a mapping file (roles → the user's node and morph names, plus the transform into
// metres, +Y up, facing +Z).
struct MappedModel {
  std::uint32_t model = 0;
  glm::mat4 correction{1.0f};
  std::optional<scene::AssetMapping> mapping;

  std::string node_name(std::string_view role) const {
    return mapping ? std::string(mapping->node(role)) : std::string(role);
  }
  std::string morph_name(std::string_view role) const {
    return mapping ? std::string(mapping->morph(role)) : std::string(role);
  }
};

glm::mat4 mapping_correction(const scene::AssetMapping& mapping) {
  const auto f = [](double v) { return static_cast<float>(v); };
  glm::mat4 m = glm::translate(glm::mat4(1.0f),
                               glm::vec3(f(mapping.translation_m.x), f(mapping.translation_m.y),
                                         f(mapping.translation_m.z)));
  m = glm::rotate(m, glm::radians(f(mapping.rotation_deg.z)), glm::vec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(f(mapping.rotation_deg.y)), glm::vec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(f(mapping.rotation_deg.x)), glm::vec3(1, 0, 0));
  return glm::scale(m, glm::vec3(f(mapping.scale)));
}

Result<MappedModel> load_mapped(ModelCache& cache, const std::filesystem::path& mapping_file,
                                const std::string& generated_file) {
  MappedModel out;
  if (mapping_file.empty()) {
    auto model = cache.get(generated_file);
    if (!model) return model.error();
    out.model = *model;
    return out;
  }
  auto mapping = scene::load_asset_mapping(mapping_file);
  if (!mapping) return mapping.error();
  auto model = cache.get_user(mapping->model);
  if (!model) return model.error();
  out.model = *model;
  out.correction = mapping_correction(*mapping);
  out.mapping = std::move(*mapping);
  return out;
}

// The node playing `role`: -1 when unmapped; an error when the mapping names a node the model
// lacks.
Result<int> find_role(const Stage& stage, const MappedModel& m, std::string_view role) {
  const std::string name = m.node_name(role);
  if (name.empty()) return -1;
  const int node = stage.models[m.model]->find_node(name);
  if (node < 0 && m.mapping) {
    return Error{m.mapping->source + ": node \"" + name + "\" for \"" + std::string(role) +
                 "\" is not in " + m.mapping->model.filename().string()};
  }
  return node;
}

// Direction `tutti_direction` (model frame after the correction) in the local frame of `node`'s
// parent at rest, so a translation along it moves the node that way whatever the user's axes.
glm::vec3 local_axis(const model::ModelAsset& asset, int node, const glm::mat4& correction,
                     const glm::vec3& tutti_direction) {
  if (node < 0) return tutti_direction;
  std::vector<glm::mat4> world(asset.nodes.size());
  model::compute_world_matrices(asset, model::rest_pose(asset), correction, world);
  const int parent = asset.nodes[static_cast<std::size_t>(node)].parent;
  const glm::mat3 frame =
      parent >= 0 ? glm::mat3(world[static_cast<std::size_t>(parent)]) : glm::mat3(correction);
  return glm::inverse(frame) * tutti_direction;
}

int morph_index(const model::ModelAsset& asset, const std::string& name) {
  if (name.empty()) return -1;
  std::size_t base = 0;
  for (const model::Mesh& mesh : asset.meshes) {
    for (std::size_t k = 0; k < mesh.target_names.size(); ++k) {
      if (mesh.target_names[k] == name) return static_cast<int>(base + k);
    }
    base += mesh.target_names.size();
  }
  return -1;
}

Result<BodyNodes> find_body_nodes(const Stage& stage, const MappedModel& body) {
  BodyNodes n;
  int* const slots[] = {&n.hips,         &n.spine,           &n.chest,           &n.neck,
                        &n.head,         &n.mouth,           &n.arm_left.upper,  &n.arm_left.lower,
                        &n.arm_left.end, &n.arm_right.upper, &n.arm_right.lower, &n.arm_right.end,
                        &n.thigh_left,   &n.thigh_right,     &n.shin_left,       &n.shin_right,
                        &n.grip_left,    &n.grip_right};
  const char* const roles[] = {"hips",      "spine",       "chest",     "neck",    "head",
                               "mouth",     "upper_arm_l", "forearm_l", "hand_l",  "upper_arm_r",
                               "forearm_r", "hand_r",      "thigh_l",   "thigh_r", "shin_l",
                               "shin_r",    "grip_l",      "grip_r"};
  for (std::size_t i = 0; i < std::size(roles); ++i) {
    auto node = find_role(stage, body, roles[i]);
    if (!node) return node.error();
    *slots[i] = *node;
  }
  const char* const finger_names[5] = {"thumb", "index", "middle", "ring", "little"};
  for (std::size_t side = 0; side < 2; ++side) {
    for (std::size_t f = 0; f < 5; ++f) {
      for (std::size_t s = 0; s < 3; ++s) {
        auto node = find_role(
            stage, body,
            std::string(finger_names[f]) + "_" + std::to_string(s + 1) + (side == 0 ? "_l" : "_r"));
        if (!node) return node.error();
        n.fingers[side][f][s] = *node;
      }
    }
  }
  const model::ModelAsset& asset = *stage.models[body.model];
  n.morph_tension = morph_index(asset, body.morph_name("tension"));
  n.morph_open = morph_index(asset, body.morph_name("open"));
  n.mapped = body.mapping.has_value();
  return n;
}

double extra_number(const model::ModelAsset&, int, const char*, double fallback) {
  // Node extras are not kept by the loader yet; the generator's defaults are used.
  return fallback;
}

std::string times_key(const std::vector<double>& times) {
  std::string out;
  char text[32];
  for (double t : times) {
    std::snprintf(text, sizeof text, "%.17g,", t);
    out += text;
  }
  return out;
}

// Everything a brass player's own plan (line, fingering, breaths, valves / slide) depends on.
std::string brass_plan_key(const scene::Scene& scene, const scene::Performer& performer) {
  return performer.instrument + "|" + performer.part + "|" + std::to_string(performer.voice) + "|" +
         scene.music[performer.music_file].string() + "|" + times_key(performer.breaths.add_s) +
         "|" + times_key(performer.breaths.remove_s);
}

// What the pianist's fingering without the scene's pins depends on.
std::string pianist_base_key(const scene::Scene& scene, const scene::Pianist& pianist) {
  std::string key = scene.music[pianist.music_file].string() + "|" + pianist.hand_size + "|";
  for (const std::string& part : pianist.parts) key += part + ",";
  return key;
}

// Everything the pianist's plan depends on.
std::string pianist_plan_key(const scene::Scene& scene, const scene::Pianist& pianist) {
  std::string key = pianist_base_key(scene, pianist);
  if (!pianist.style.empty() || pianist.sound_from_keys) {
    key += "|style " + pianist.style + (pianist.sound_from_keys ? " keys " : " score ") +
           std::to_string(pianist.seed);
  }
  char text[64];
  for (const scene::FingerPin& pin : pianist.pins) {
    std::snprintf(text, sizeof text, "|%.17g:%d:%d", pin.time_s, pin.key, pin.finger);
    key += text;
  }
  return key;
}

Status build_brass(Stage& stage, ModelCache& cache) {
  if (stage.scene.performers.empty()) return Status::success();
  auto weights = brass::load_planner_weights();
  if (!weights) return weights.error();
  auto motion = brass::load_brass_motion_params();
  if (!motion) return motion.error();
  auto breath = brass::load_breath_params();
  if (!breath) return breath.error();
  // The performer rig is not generated yet (content/generator/README.md): until it is, players
  // are their instruments at mouth height.
  const bool rig_generated = std::filesystem::exists(cache.dir() / "performer.glb");
  auto stand_model = cache.get("music_stand.glb");
  if (!stand_model) return stand_model.error();
  auto chair_model = cache.get("chair.glb");
  if (!chair_model) return chair_model.error();

  std::vector<ensemble::PerformerInput> ensemble_inputs;
  for (std::size_t seat_index = 0; seat_index < stage.scene.performers.size(); ++seat_index) {
    const scene::Performer& performer = stage.scene.performers[seat_index];
    const music::Score& score = stage.scores[performer.music_file];
    const std::string key = brass_plan_key(stage.scene, performer);
    const Stage* reuse = cache.reused();
    const BrassSeat* previous = reuse != nullptr && seat_index < reuse->brass.size() &&
                                        reuse->brass[seat_index].plan_key == key &&
                                        reuse->brass[seat_index].planned_line != nullptr
                                    ? &reuse->brass[seat_index]
                                    : nullptr;
    std::shared_ptr<const brass::BrassLine> line;
    std::shared_ptr<const brass::BrassPlayerMotion> player;
    std::vector<std::string> plan_notes;
    if (previous != nullptr) {
      stage.instruments.push_back(reuse->instruments[seat_index]);
      line = previous->planned_line;
      player = reuse->ensemble_players[seat_index];
      plan_notes = previous->plan_notes;
    } else {
      auto instrument = brass::load_instrument_by_id(performer.instrument);
      if (!instrument) return instrument.error();
      // The lines point at their instrument: it lives as long as the stage.
      stage.instruments.push_back(
          std::make_shared<const brass::Instrument>(std::move(*instrument)));
      const int part = scene::find_part(score, performer.part);
      if (part < 0) {
        return Error{stage.scene.source + ": performer \"" + performer.name + "\": no part \"" +
                     performer.part + "\" in " +
                     stage.scene.music[performer.music_file].filename().string()};
      }
      auto extracted =
          brass::extract_line(score, part, performer.voice - 1, *stage.instruments.back());
      if (!extracted) {
        return Error{stage.scene.source + ": performer \"" + performer.name +
                     "\": " + extracted.error().message};
      }
      const brass::BrassPlanSummary summary = brass::plan_line(*extracted, *weights, &score);
      for (const brass::BrassDiagnostic& d : summary.diagnostics) {
        plan_notes.push_back(performer.name + ": " + d.message);
      }
      brass::BreathMarks marks;
      marks.add_s = performer.breaths.add_s;
      marks.remove_s = performer.breaths.remove_s;
      player = std::make_shared<const brass::BrassPlayerMotion>(
          brass::plan_brass_player(*extracted, score, *motion, *breath, weights->change, marks));
      line = std::make_shared<const brass::BrassLine>(std::move(*extracted));
      stage.replanned.push_back(performer.name);
    }
    stage.notes.insert(stage.notes.end(), plan_notes.begin(), plan_notes.end());
    const brass::Instrument& played = *stage.instruments.back();
    music::Score& heard = stage.sounding[performer.music_file];
    for (const brass::ShortenedNote& shortened : player->breaths.shortened) {
      if (shortened.note < 0 || static_cast<std::size_t>(shortened.note) >= line->notes.size()) {
        continue;
      }
      const int index = line->notes[static_cast<std::size_t>(shortened.note)].score_index;
      if (index < 0 || static_cast<std::size_t>(index) >= heard.notes.size()) continue;
      music::Note& note = heard.notes[static_cast<std::size_t>(index)];
      note.offset_s = std::clamp(shortened.offset_s, note.onset_s, note.offset_s);
      note.offset_beats = std::clamp(shortened.offset_beats, note.onset_beats, note.offset_beats);
    }

    BrassSeat seat;
    seat.name = performer.name;
    seat.trombone = played.mechanism == brass::Mechanism::slide;
    seat.seated = performer.stance == scene::Stance::seated;
    seat.placement = placement_matrix(performer.position_m, performer.facing_deg);
    seat.performer = stage.world.create();
    stage.world.add<components::Performer>(seat.performer,
                                           components::Performer{performer.name, performer.seed});
    stage.world.add<brass::BrassPlayerMotionHandle>(seat.performer,
                                                    brass::BrassPlayerMotionHandle{player});
    stage.world.add<components::Mouth>(seat.performer);
    stage.world.add<components::Breath>(seat.performer);
    seat.instrument = stage.world.create();
    stage.world.add<components::Instrument>(seat.instrument,
                                            components::Instrument{played.id, seat.performer});
    if (seat.trombone) {
      stage.world.add<components::Slide>(seat.instrument);
    } else {
      components::Valve valve;
      valve.count = static_cast<std::uint8_t>(std::min<std::size_t>(played.valves.size(), 6));
      stage.world.add<components::Valve>(seat.instrument, valve);
    }

    auto horn = load_mapped(cache, performer.instrument_mapping,
                            seat.trombone ? "trombone.glb" : "trumpet.glb");
    if (!horn) return horn.error();
    if (rig_generated || !performer.character_mapping.empty()) {
      auto body = load_mapped(cache, performer.character_mapping, "performer.glb");
      if (!body) return body.error();
      seat.body = cache.place(body->model, seat.placement * body->correction);
      auto nodes = find_body_nodes(stage, *body);
      if (!nodes) return nodes.error();
      seat.body_nodes = *nodes;
    }
    seat.horn = cache.place(horn->model, seat.placement);
    seat.horn_correction = horn->correction;
    const model::ModelAsset& horn_asset = *stage.models[horn->model];
    for (std::size_t v = 0; v < 3; ++v) {
      auto node = find_role(stage, *horn, "valve_" + std::to_string(v + 1));
      if (!node) return node.error();
      seat.valves[v] = *node;
      seat.valve_axis[v] = local_axis(horn_asset, *node, horn->correction, {0, -1, 0});
      seat.valve_travel_m[v] = extra_number(horn_asset, *node, "travel_mm", 18.0) / 1000.0;
    }
    for (auto [slot, role] : {std::pair{&seat.slide, "slide"},
                              {&seat.mouthpiece, "mouthpiece"},
                              {&seat.grip_left, "grip_left"},
                              {&seat.grip_right, "grip_right"}}) {
      auto node = find_role(stage, *horn, role);
      if (!node) return node.error();
      *slot = *node;
    }
    seat.slide_axis = local_axis(horn_asset, seat.slide, horn->correction, {0, 0, -1});
    if (performer.music_stand) {
      // The stand 0.75 m in front of the player, desk toward them.
      const glm::mat4 stand = glm::rotate(glm::translate(seat.placement, glm::vec3(0, 0, 0.75f)),
                                          glm::radians(180.0f), glm::vec3(0, 1, 0));
      cache.place(*stand_model, stand);
    }
    if (seat.seated) {
      cache.place(*chair_model, glm::translate(seat.placement, glm::vec3(0, 0, -0.12f)));
    }
    for (const brass::LineNote& note : line->notes) {
      seat.line.push_back(LineNoteTime{note.onset_s, note.offset_s, note.sounding, note.playable});
    }
    seat.plan_key = key;
    seat.planned_line = line;
    seat.plan_notes = std::move(plan_notes);
    stage.brass.push_back(seat);

    ensemble::PerformerInput input;
    input.seed = performer.seed;
    input.params = ensemble::resolve_variation(performer.seed, performer.variation);
    input.lead = performer.lead;
    input.score = &score;
    input.breaths = &player->breaths;
    for (const scene::Expression& e : performer.expressions) {
      ensemble::ExpressionSpan span;
      span.kind = e.kind == scene::ExpressionKind::strain ? ensemble::ExpressionKind::strain
                                                          : ensemble::ExpressionKind::relaxed;
      span.start_s = e.start_s;
      span.end_s = e.end_s;
      span.amount = e.amount;
      input.expressions.push_back(span);
    }
    if (!player->motion.sounding.empty()) {
      input.first_onset_s = player->motion.sounding.front().onset_s;
      input.last_offset_s = player->motion.sounding.back().offset_s;
    }
    ensemble_inputs.push_back(input);
    stage.ensemble_players.push_back(player);
  }
  brass::register_brass_motion(stage.schedule);
  if (!stage.brass.empty()) {
    ensemble::EnsembleOptions ensemble_options;
    ensemble_options.cues_s = stage.scene.cues_s;
    auto ensemble_plan = ensemble::plan_ensemble(ensemble_inputs, ensemble_options);
    stage.replanned.push_back("ensemble");
    if (!ensemble_plan) return ensemble_plan.error();
    stage.ensemble = std::make_shared<const ensemble::EnsemblePlan>(std::move(*ensemble_plan));
    for (std::size_t i = 0; i < stage.brass.size(); ++i) {
      stage.world.add<ensemble::EnsembleMotionHandle>(
          stage.brass[i].performer, ensemble::EnsembleMotionHandle{stage.ensemble, i});
      stage.world.add<components::BodyMotion>(stage.brass[i].performer);
    }
    ensemble::register_ensemble_variation(stage.schedule);
  }
  return Status::success();
}

// The editor's pins become the planner's pins (Note::finger, plan_score's pins_from_marks). A
// pin names its note by key and onset; one that matches no note is an error, not ignored.
Status apply_finger_pins(const scene::Scene& scene, const scene::Pianist& pianist,
                         music::Score& score) {
  constexpr double kSameOnset_s = 1e-3;
  for (std::size_t i = 0; i < pianist.pins.size(); ++i) {
    const scene::FingerPin& pin = pianist.pins[i];
    music::Note* pinned = nullptr;
    for (music::Note& note : score.notes) {
      if (note.pitch == pin.key && std::abs(note.onset_s - pin.time_s) < kSameOnset_s) {
        pinned = &note;
        break;
      }
    }
    if (pinned == nullptr) {
      char time[32];
      std::snprintf(time, sizeof time, "%.3f", pin.time_s);
      return Error{scene.source + ": /pianist/pins/" + std::to_string(i) + ": no note of key " +
                   std::to_string(pin.key) + " starts at " + time +
                   " s in the pianist's parts of " +
                   scene.music[pianist.music_file].filename().string()};
    }
    pinned->finger = pin.finger;
  }
  return Status::success();
}

// The pianist's motion in the scene's performance style, and what the keys make of it.
Result<key_action::HumanePerformance> perform_in_style(
    const scene::Scene& scene, const scene::Pianist& pianist, const music::Score& score,
    const performance::PianoPerformancePlan& paths, const piano::FingeringModel& model,
    const finger_motion::FingerMotionParams& params, const std::filesystem::path& content_dir) {
  auto styles = key_action::load_styles(key_action::styles_path(content_dir));
  if (!styles) return styles.error();
  auto style = styles->find(pianist.style.empty() ? "precise" : pianist.style);
  if (!style) return Error{scene.source + ": /pianist/style: " + style.error().message};
  auto action = key_action::load_key_action(key_action::key_action_path(content_dir));
  if (!action) return action.error();
  key_action::HumaneInputs in;
  in.score = &score;
  in.fingering = &paths.fingering;
  in.right_path = &paths.right_path;
  in.left_path = &paths.left_path;
  in.keyboard = &model.keyboard;
  in.hand_model = &model.hand;
  in.params = &params;
  in.action = &*action;
  in.style = &*style;
  in.seed = pianist.seed;
  return key_action::perform(in);
}

// The piano notes of `heard` as the keys sounded them; notes that did not sound are removed.
void hear_the_keys(const std::vector<key_action::PlayedNote>& played,
                   const std::vector<std::size_t>& full_index, music::Score& heard) {
  std::vector<char> silent(heard.notes.size(), 0);
  for (std::size_t i = 0; i < played.size() && i < full_index.size(); ++i) {
    const key_action::PlayedNote& p = played[i];
    if (p.outcome == key_action::KeyOutcome::not_played) continue;
    if (full_index[i] >= heard.notes.size()) continue;
    if (p.outcome != key_action::KeyOutcome::sounded) {
      silent[full_index[i]] = 1;
      continue;
    }
    music::Note& note = heard.notes[full_index[i]];
    // As key_action::performed_score: nothing sounds before the music's time 0.
    note.onset_s = std::max(p.onset_s, 0.0);
    note.offset_s = std::max(note.onset_s, p.offset_s);
    note.velocity = p.velocity;
  }
  std::size_t kept = 0;
  for (std::size_t j = 0; j < heard.notes.size(); ++j) {
    if (!silent[j]) heard.notes[kept++] = heard.notes[j];
  }
  heard.notes.resize(kept);
}

Status build_pianist(Stage& stage, ModelCache& cache, const std::filesystem::path& content_dir) {
  if (!stage.scene.pianist) return Status::success();
  const scene::Pianist& pianist = *stage.scene.pianist;
  if (!pianist.hands_mapping.empty() || !pianist.character_mapping.empty()) {
    return Error{stage.scene.source +
                 ": pianist: user hand and character models are not "
                 "supported yet (the brass players' are); remove \"hands\" / \"character\""};
  }
  const music::Score& full = stage.scores[pianist.music_file];
  // Only the parts the pianist plays.
  music::Score score = full;
  std::vector<bool> played(full.parts.size(), false);
  for (const std::string& name : pianist.parts) {
    const int part = scene::find_part(full, name);
    if (part < 0) {
      return Error{stage.scene.source + ": pianist: no part \"" + name + "\" in " +
                   stage.scene.music[pianist.music_file].filename().string()};
    }
    played[static_cast<std::size_t>(part)] = true;
  }
  score.notes.clear();
  std::vector<std::size_t> full_index;  // seat score note -> stage score note
  for (std::size_t i = 0; i < full.notes.size(); ++i) {
    if (played[static_cast<std::size_t>(full.notes[i].part)]) {
      score.notes.push_back(full.notes[i]);
      full_index.push_back(i);
    }
  }
  // The editor's pins act locally: the fingering without them (the file's own marks are pins
  // there too) is planned once, then only the span around the pinned notes is searched again
  // (piano::replan_score_locally). A pure function of the score and the pins, so the editor and
  // `tutti render` get the same fingering whatever order the pins were placed in.
  const music::Score unpinned = score;
  if (Status s = apply_finger_pins(stage.scene, pianist, score); !s) return s.error();
  std::vector<int> pinned_notes;
  for (std::size_t i = 0; i < score.notes.size(); ++i) {
    if (score.notes[i].finger != unpinned.notes[i].finger)
      pinned_notes.push_back(static_cast<int>(i));
  }
  auto model = piano::load_fingering_model("default", pianist.hand_size, content_dir);
  if (!model) return model.error();
  const std::string base_key = pianist_base_key(stage.scene, pianist);
  const std::string plan_key = pianist_plan_key(stage.scene, pianist);
  const Stage* reuse = cache.reused();
  const PianistSeat* previous = reuse != nullptr && reuse->pianist ? reuse->pianist.get() : nullptr;
  std::shared_ptr<const finger_motion::PianistMotion> motion;
  piano::ScorePlan fingering;
  piano::ScorePlan base;
  std::vector<std::string> plan_notes;
  std::shared_ptr<const std::vector<key_action::PlayedNote>> played_notes;
  key_action::PerformanceReport performance_report;
  if (previous != nullptr && previous->plan_key == plan_key && previous->motion) {
    motion = previous->motion;
    fingering = previous->fingering;
    base = previous->base_fingering;
    plan_notes = previous->plan_notes;
    played_notes = previous->played;
    performance_report = previous->performance;
  } else {
    if (previous != nullptr && previous->base_key == base_key) {
      base = previous->base_fingering;
    } else {
      auto planned = piano::plan_score(unpinned, *model);
      if (!planned) return planned.error();
      base = std::move(*planned);
      stage.replanned.push_back("pianist fingering");
    }
    fingering = base;
    if (!pinned_notes.empty()) {
      piano::ScoreReplanSpan span;
      auto replanned = piano::replan_score_locally(score, *model, {}, base, pinned_notes, &span);
      if (!replanned) return replanned.error();
      fingering = std::move(*replanned);
      stage.replanned.push_back("pianist fingering around the pins (" +
                                std::to_string(span.searched_events) + " of " +
                                std::to_string(span.event_count) + " events)");
    }
    performance::PianoPerformancePlan performance = performance::plan_performance_paths(fingering);
    for (const performance::HandReport* hand :
         {&performance.report.right, &performance.report.left}) {
      if (!hand->path_error.empty()) plan_notes.push_back("pianist: " + hand->path_error);
    }
    auto params = finger_motion::load_finger_motion_params(
        finger_motion::finger_motion_params_path(content_dir));
    if (!params) return params.error();
    if (!pianist.style.empty() || pianist.sound_from_keys) {
      auto humane =
          perform_in_style(stage.scene, pianist, score, performance, *model, *params, content_dir);
      if (!humane) return humane.error();
      motion = std::move(humane->motion);
      performance_report = humane->report;
      played_notes =
          std::make_shared<const std::vector<key_action::PlayedNote>>(std::move(humane->played));
    } else {
      auto fingers = finger_motion::plan_finger_motion(
          score, performance.fingering, performance.right_path, performance.left_path,
          model->keyboard, model->hand, *params);
      if (!fingers) return fingers.error();
      auto planned_motion = std::make_shared<finger_motion::PianistMotion>();
      planned_motion->fingers = std::move(*fingers);
      planned_motion->right_path = std::move(performance.right_path);
      planned_motion->left_path = std::move(performance.left_path);
      motion = std::move(planned_motion);
    }
    stage.replanned.push_back("pianist motion");
  }
  stage.notes.insert(stage.notes.end(), plan_notes.begin(), plan_notes.end());

  auto seat = std::make_unique<PianistSeat>();
  seat->fingering = std::move(fingering);
  seat->score = std::move(score);
  seat->motion = motion;
  seat->plan_key = plan_key;
  seat->base_key = base_key;
  seat->base_fingering = std::move(base);
  seat->plan_notes = std::move(plan_notes);
  if (pianist.sound_from_keys && played_notes) {
    hear_the_keys(*played_notes, full_index, stage.sounding[pianist.music_file]);
  }
  seat->played = std::move(played_notes);
  seat->performance = performance_report;
  seat->pianist = stage.world.create();
  stage.world.add<components::Performer>(seat->pianist,
                                         components::Performer{"pianist", pianist.seed});
  stage.world.add<finger_motion::PianistMotionHandle>(seat->pianist,
                                                      finger_motion::PianistMotionHandle{motion});
  for (int side = 0; side < 2; ++side) {
    const auto hand_side = side == 0 ? components::HandSide::right : components::HandSide::left;
    const ecs::Entity hand = stage.world.create();
    components::Hand hand_value;
    hand_value.side = hand_side;
    hand_value.performer = seat->pianist;
    stage.world.add<components::Hand>(hand, hand_value);
    seat->hands[static_cast<std::size_t>(side)] = hand;
    for (int f = 0; f < 5; ++f) {
      const ecs::Entity finger = stage.world.create();
      components::Finger finger_value;
      finger_value.hand = hand;
      finger_value.side = hand_side;
      finger_value.finger = f + 1;
      stage.world.add<components::Finger>(finger, finger_value);
      seat->fingers[static_cast<std::size_t>(side)][static_cast<std::size_t>(f)] = finger;
    }
  }
  finger_motion::register_finger_motion(stage.schedule);

  auto piano_model = cache.get("piano.glb");
  if (!piano_model) return piano_model.error();
  seat->piano = cache.place(*piano_model, glm::mat4(1.0f));
  const model::ModelAsset& piano = *stage.models[*piano_model];
  seat->key_nodes.fill(-1);
  seat->key_dip_rad.fill(0.0);
  for (int key = 0; key < 128; ++key) {
    seat->key_nodes[static_cast<std::size_t>(key)] = piano.find_node("key_" + std::to_string(key));
    // 10 mm at the front of the key: 150 mm from the pivot for white keys, 95 mm for black.
    const bool black = model->keyboard.contains(key) && model->keyboard.is_black(key);
    seat->key_dip_rad[static_cast<std::size_t>(key)] = std::atan(10.0 / (black ? 95.0 : 150.0));
  }
  {
    std::vector<glm::mat4> world(piano.nodes.size());
    model::compute_world_matrices(piano, stage.placed[seat->piano].pose, glm::mat4(1.0f), world);
    const int keyboard = piano.find_node("keyboard");
    if (keyboard >= 0) seat->keyboard_to_world = world[static_cast<std::size_t>(keyboard)];
  }
  const char* finger_names[5] = {"thumb", "index", "middle", "ring", "little"};
  for (int side = 0; side < 2; ++side) {
    auto hand_model = cache.get(side == 0 ? "hand_right.glb" : "hand_left.glb");
    if (!hand_model) return hand_model.error();
    seat->hand_models[static_cast<std::size_t>(side)] = cache.place(*hand_model, glm::mat4(1.0f));
    const model::ModelAsset& hand = *stage.models[*hand_model];
    seat->hand_root[static_cast<std::size_t>(side)] = hand.roots.empty() ? -1 : hand.roots[0];
    for (int f = 0; f < 5; ++f) {
      for (int s = 0; s < 3; ++s) {
        seat->finger_bones[static_cast<std::size_t>(side)][static_cast<std::size_t>(f)]
                          [static_cast<std::size_t>(s)] = hand.find_node(
            std::string(finger_names[f]) + "_" + std::to_string(s + 1) + (side == 0 ? "_r" : "_l"));
      }
    }
  }
  auto chair_model = cache.get("chair.glb");
  if (!chair_model) return chair_model.error();
  // The chair's front (+Z) toward the keys, like the pianist.
  const glm::mat4 bench = placement_matrix(pianist.position_m, pianist.facing_deg);
  cache.place(*chair_model, bench);
  if (std::filesystem::exists(cache.dir() / "performer.glb")) {
    auto body = load_mapped(cache, {}, "performer.glb");
    if (!body) return body.error();
    seat->body = cache.place(body->model, bench);
    auto nodes = find_body_nodes(stage, *body);
    if (!nodes) return nodes.error();
    seat->body_nodes = *nodes;
    for (int side = 0; side < 2; ++side) {
      auto hand = find_role(stage, *body, side == 0 ? "hand_r" : "hand_l");
      if (!hand) return hand.error();
      seat->rig_hands[static_cast<std::size_t>(side)] = *hand;
    }
  }
  stage.pianist = std::move(seat);
  return Status::success();
}

}  // namespace

std::filesystem::path default_asset_dir() {
  if (const char* dir = std::getenv("TUTTI_ASSET_DIR"); dir != nullptr && *dir != '\0') {
    return dir;
  }
  return TUTTI_DEFAULT_ASSET_DIR;
}

std::vector<const model::ModelAsset*> Stage::model_list() const {
  std::vector<const model::ModelAsset*> list;
  for (const auto& m : models) list.push_back(m.get());
  return list;
}

Result<std::unique_ptr<Stage>> build_stage(const scene::Scene& scene, const StageOptions& options) {
  auto stage = std::make_unique<Stage>();
  stage->scene = scene;
  const std::filesystem::path content_dir =
      options.content_dir.empty() ? content::default_content_dir() : options.content_dir;
  double music_end = 0.0;
  for (const std::filesystem::path& file : scene.music) {
    auto score = music::load_score(file);
    if (!score) return score.error();
    music_end = std::max(music_end, score->duration_s());
    stage->scores.push_back(std::move(*score));
  }
  stage->sounding = stage->scores;
  ModelCache cache(*stage, options.asset_dir.empty() ? default_asset_dir() : options.asset_dir);
  cache.reuse(options.reuse_models);
  auto floor = cache.get("stage.glb");
  if (!floor) return floor.error();
  stage->placed[cache.place(*floor, glm::mat4(1.0f))].casts_shadows = false;
  if (Status s = build_brass(*stage, cache); !s) return s.error();
  if (Status s = build_pianist(*stage, cache, content_dir); !s) return s.error();
  stage->start_s = scene.output.start_s;
  stage->end_s = scene.output.end_s ? *scene.output.end_s : music_end + 1.0;
  return stage;
}

}  // namespace tutti::stage
