#pragma once
// Stage: a scene made ready to play. build_stage() does everything offline once — loads the
// music and the models, plans the pianist (fingering, hand paths, finger motion) and every brass
// player (fingering, valves/slide/embouchure, breaths), and wires the ECS world — and
// evaluate_stage(t) poses it all at time t: the systems write the components (Phase::evaluate),
// then the pose step turns components into node transforms and morph weights (Phase::pose).
//
// The pose at t is a pure function of the plans and t (ozz-animation's offline/runtime split):
// frames can be rendered in any order, on any machine, with identical results.

#include <array>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/ecs/schedule.hpp>
#include <tutti/ecs/world.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/key_action/key_simulation.hpp>
#include <tutti/key_action/performance_report.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/music/score.hpp>
#include <tutti/render/model_renderer.hpp>
#include <tutti/scene/scene.hpp>
#include <tutti/stage/two_bone_ik.hpp>

namespace tutti::ensemble {
struct EnsemblePlan;
}
namespace tutti::brass {
struct BrassPlayerMotion;
}

namespace tutti::brass {
struct Instrument;
struct BrassLine;
}  // namespace tutti::brass
namespace tutti::finger_motion {
struct PianistMotion;
}

namespace tutti::stage {

struct Stage;

struct StageOptions {
  std::filesystem::path content_dir;  // empty: tutti::content::default_content_dir()
  std::filesystem::path asset_dir;    // the generated .glb files; empty: default_asset_dir()
  // Models already loaded (the editor re-plans after every edit): files this stage loaded are
  // shared instead of read again, so a renderer made for its model_list() stays valid when the
  // scene's cast is unchanged.
  const Stage* reuse_models = nullptr;
};

// Where the content generator's .glb files are: $TUTTI_ASSET_DIR, else the build tree's
// content/assets (compiled in).
std::filesystem::path default_asset_dir();

// One model instance on the stage: which model, where, and its pose this frame.
struct PlacedModel {
  std::uint32_t model = 0;  // index into Stage::models
  glm::mat4 root{1.0f};
  model::ModelPose pose;
  bool casts_shadows = true;  // the floor does not (it is under everything)
};

// Node indices in the default performer rig (-1 where the model lacks one).
struct BodyNodes {
  int hips = -1, spine = -1, chest = -1, neck = -1, head = -1, mouth = -1;
  int grip_left = -1, grip_right = -1;  // palm centres, turned into the hand asset's frame
  TwoBoneChain arm_left, arm_right;
  int thigh_left = -1, thigh_right = -1, shin_left = -1, shin_right = -1;
  int morph_tension = -1, morph_open = -1;  // indices into the pose's morph_weights
  // Finger bones [left, right][thumb .. little][segment], for the grip curls.
  std::array<std::array<std::array<int, 3>, 5>, 2> fingers{};
  bool mapped = false;  // a user's rig (mapping file): only IK and morphs, no canned bends
};

// One note of a brass player's line, as written (BreathEvent::before_note indexes these).
struct LineNoteTime {
  double onset_s = 0.0;
  double offset_s = 0.0;
  int pitch = 60;  // sounding MIDI key
  bool playable = true;
};

struct BrassSeat {
  std::string name;
  std::vector<LineNoteTime> line;
  // What this player's plan was made from (instrument, part, voice, music, breath marks): a
  // re-plan with the same key shares the plan instead of making it again.
  std::string plan_key;
  std::shared_ptr<const brass::BrassLine> planned_line;
  std::vector<std::string> plan_notes;  // the planner's diagnostics for this player
  ecs::Entity performer = ecs::Entity::null;
  ecs::Entity instrument = ecs::Entity::null;
  bool trombone = false;
  bool seated = false;
  std::optional<std::size_t> body;  // into Stage::placed; none until the rig is generated
  std::size_t horn = 0;
  BodyNodes body_nodes;
  std::array<int, 3> valves{-1, -1, -1};
  std::array<double, 3> valve_travel_m{0.0, 0.0, 0.0};
  // Press and slide directions in the nodes' parent frames (tutti's −Y and −Z there; a user's
  // model may have other axes).
  std::array<glm::vec3, 3> valve_axis{glm::vec3(0, -1, 0), glm::vec3(0, -1, 0),
                                      glm::vec3(0, -1, 0)};
  glm::vec3 slide_axis{0, 0, -1};
  glm::mat4 horn_correction{1.0f};  // a user's instrument into tutti's frame (mapping file)
  int slide = -1;
  int mouthpiece = -1, grip_left = -1, grip_right = -1;
  glm::mat4 placement{1.0f};  // feet on the floor, facing
};

struct PianistSeat {
  // What the pianist plays (their parts, pins applied) and the fingering planned for it: the
  // editor shows and pins fingers on these notes.
  music::Score score;
  piano::ScorePlan fingering;
  std::shared_ptr<const finger_motion::PianistMotion> motion;
  std::string plan_key;  // parts, music, hand size, pins: as BrassSeat::plan_key
  // The fingering before the scene's pins (the file's own marks pinned) and what it depends on:
  // pins re-plan only the span around them from it.
  piano::ScorePlan base_fingering;
  std::string base_key;
  std::vector<std::string> plan_notes;
  // With a performance style (scene pianist "style" / "sound": "keys"): what the simulated keys
  // did with each note of `score` (systems/key_action), and its summary. Empty without a style.
  std::shared_ptr<const std::vector<key_action::PlayedNote>> played;
  key_action::PerformanceReport performance;
  ecs::Entity pianist = ecs::Entity::null;
  std::array<ecs::Entity, 2> hands{ecs::Entity::null, ecs::Entity::null};  // right, left
  std::array<std::array<ecs::Entity, 5>, 2> fingers{};
  std::size_t piano = 0;
  std::array<std::size_t, 2> hand_models{0, 0};  // into Stage::placed; right, left
  // The seated performer rig (when generated): arms reach the hand models' wrists; the rig's
  // own hands are folded away (scale 0) because the hand models draw them.
  std::optional<std::size_t> body;
  BodyNodes body_nodes;
  std::array<int, 2> rig_hands{-1, -1};  // right, left
  std::array<int, 128> key_nodes{};      // piano node per MIDI key, -1 = none
  std::array<double, 128> key_dip_rad{};
  glm::mat4 keyboard_to_world{1.0f};  // the piano's `keyboard` node (metres, glTF axes)
  // Bones of each hand model, [finger 0..4][segment 0..2]; -1 = missing.
  std::array<std::array<std::array<int, 3>, 5>, 2> finger_bones{};
  std::array<int, 2> hand_root{-1, -1};
};

struct Stage {
  scene::Scene scene;
  std::vector<music::Score> scores;  // one per scene music file
  // What is heard: `scores` with the notes as the players play them (a brass note shortened to
  // make room for a catch breath ends early here, so the sound stops while the player breathes;
  // with the pianist's "sound": "keys", the piano notes as the keys sounded them, missed ones
  // left out).
  std::vector<music::Score> sounding;
  std::vector<std::shared_ptr<const model::ModelAsset>> models;
  std::vector<std::string> model_files;  // the file each of `models` came from
  std::vector<PlacedModel> placed;
  std::vector<BrassSeat> brass;
  // The ensemble's body motion (every brass player, in `brass` order) and the brass plans it
  // points into (kept alive here).
  std::shared_ptr<const ensemble::EnsemblePlan> ensemble;
  std::vector<std::shared_ptr<const brass::BrassPlayerMotion>> ensemble_players;
  std::unique_ptr<PianistSeat> pianist;
  ecs::World world;
  ecs::Schedule schedule;
  double start_s = 0.0;
  double end_s = 0.0;  // output end (scene's end_s, else the end of the music + 1 s)
  std::vector<std::shared_ptr<const brass::Instrument>> instruments;  // the brass players'
  std::vector<std::string> notes;  // planning diagnostics worth showing (out of range, ...)
  // What build_stage planned afresh (performer names, "pianist", "ensemble"); with
  // StageOptions::reuse_models, everything else was shared from that stage unchanged.
  std::vector<std::string> replanned;
  std::vector<glm::mat4> scratch_world;       // reused by evaluate_stage (instrument / pianist)
  std::vector<glm::mat4> scratch_body_world;  // reused by evaluate_stage (brass players' bodies)

  std::vector<const model::ModelAsset*> model_list() const;
};

Result<std::unique_ptr<Stage>> build_stage(const scene::Scene& scene, const StageOptions& options);

// Poses everything at t_s (seconds of the music). Deterministic; allocation-free after the first
// call except inside the systems' own (allocation-free) evaluation.
void evaluate_stage(Stage& stage, double t_s);

// The model instances as the renderer wants them (pointing into stage.placed).
void collect_instances(const Stage& stage, std::vector<render::ModelInstance>& out);
render::Camera camera_at(const Stage& stage, double t_s, float aspect);
// The scene's camera number `camera` (Scene::cameras), whatever the shot list says.
render::Camera scene_camera(const Stage& stage, std::size_t camera, float aspect);
render::Lighting lighting_of(const Stage& stage);

}  // namespace tutti::stage
