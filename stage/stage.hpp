// SPDX-License-Identifier: MIT
#pragma once
// Stage: a scene made ready to play. build_stage() (build_stage.hpp) does the offline half once:
// it loads the music, lets each instrument family (FamilyPlugin) plan its performers, spawn
// their entities and bind their models, and wires the ECS world and its schedule. Stage::run(t)
// is the frame: the schedule's phases sync → evaluate → express → pose write the components and
// then the models' poses (PlacedModel) at time t.
//
// The pose at t is a pure function of the plans and t (ozz-animation's offline/runtime split):
// frames can be computed in any order, on any machine, with identical results.
//
// What a consumer reads is behind accessors: the scene, the scores, the models and their
// instances (PlacedModel entities, in placement order), the performers (entities with
// components::Performer and Seat, in family order) and the notes (components::Note entities).
// A family's own data is in its own components on its performer entities.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/ecs/schedule.hpp>
#include <tutti/ecs/world.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/music/score.hpp>
#include <tutti/scene/scene.hpp>

namespace tutti::stage {

class Stage;
class FamilyPlugin;

struct StageOptions {
  std::filesystem::path content_dir;  // empty: tutti::content::default_content_dir()
  std::filesystem::path asset_dir;    // the generated .glb files; empty: default_asset_dir()
  // Models and plans already made (the editor re-plans after every edit): files this stage
  // loaded are shared instead of read again, so a renderer made for its model_list() stays valid
  // when the scene's cast is unchanged, and a performer whose inputs did not change keeps its plan.
  const Stage* reuse_models = nullptr;
};

// Where the content generator's .glb files are: $TUTTI_ASSET_DIR; else, for an installed program,
// <prefix>/share/tutti/assets; else the build tree's content/assets (compiled in).
std::filesystem::path default_asset_dir();

// Component: one model instance on the stage — which model, where, and its pose this frame.
// The pose systems (Phase::pose) write `root` and `pose`.
struct PlacedModel {
  std::uint32_t model = 0;  // index into Stage::models()
  std::shared_ptr<const model::ModelAsset> asset;
  glm::mat4 root{1.0f};
  model::ModelPose pose;
  bool casts_shadows = true;  // the floor does not (it is under everything)
  // Whose model it is (an export puts it in their clip); null for scenery.
  ecs::Entity performer = ecs::Entity::null;
  // Its name to a user (export node names): with `after_performer`, the performer's name then
  // the label (its instrument, a hand; an empty label: the performer's body); else the label
  // alone (an instrument no one carries). Empty and no performer: "<file stem> <n>".
  std::string label;
  bool after_performer = false;
};

// Component on every performer entity: the family that plays it, which of the family's
// performers it is (its index in the family's scene section), the id of the instrument it
// plays and where the scene file writes the player (a JSON pointer, "/<key>/2"; the editor's
// edits go there). The family sets the last two.
struct Seat {
  std::string family;
  std::size_t index = 0;
  std::string instrument;
  std::string player;
};

// A caller's own state for computing frames from a shared stage (ozz-animation's sampling
// context): a copy of the stage's world (its components, with their scratch space) in which
// Stage::run(context, ...) poses the models. The plans the components point at are shared and
// only read, so contexts on different threads sample one stage at the same time
// (Performance.FourThreadsSampleOnePlan). Made by Stage::make_context.
class StageContext {
 public:
  ecs::World& world() { return world_; }
  const ecs::World& world() const { return world_; }
  // The stage's instances()[instance] as this context last posed it.
  const PlacedModel& placed(std::size_t instance) const;

 private:
  friend class Stage;
  StageContext(const Stage& stage, ecs::World world);

  const Stage* stage_;
  ecs::World world_;
};

class Stage {
 public:
  Stage();
  ~Stage();
  Stage(const Stage&) = delete;
  Stage& operator=(const Stage&) = delete;

  const scene::Scene& scene() const { return scene_; }
  // The output range: the scene's start, and its end (else the end of the music + 1 s).
  double start_s() const { return start_s_; }
  double end_s() const { return end_s_; }

  // The music as written, one score per scene music file.
  const std::vector<music::Score>& scores() const { return scores_; }
  // What is heard, from the Note entities: `scores()` with the notes as the players play them (a
  // note shortened for a catch breath ends early, a key's note when the simulated key sounds it;
  // missed notes left out).
  std::vector<music::Score> heard_scores() const;
  // The Note entity of scores()[score].notes[index].
  ecs::Entity note_entity(std::size_t score, std::size_t index) const;

  const std::vector<std::shared_ptr<const model::ModelAsset>>& models() const { return models_; }
  const std::vector<std::string>& model_files() const { return model_files_; }
  std::vector<const model::ModelAsset*> model_list() const;

  // PlacedModel entities, in the order they were placed.
  const std::vector<ecs::Entity>& instances() const { return instances_; }
  const PlacedModel& placed(std::size_t instance) const;

  // The families it was built with, in their order (they outlive the stage).
  std::span<const FamilyPlugin* const> families() const { return families_; }

  // Performer entities (components::Performer, Seat), family by family in plugin order.
  const std::vector<ecs::Entity>& performers() const { return performers_; }
  // The performer of `family` with Seat::index `index`; null when there is none.
  ecs::Entity find_performer(std::string_view family, std::size_t index) const;

  // Planning diagnostics worth showing (out of range, ...).
  const std::vector<std::string>& notes() const { return notes_; }
  // What build_stage planned afresh (performer names, "ensemble"); with
  // StageOptions::reuse_models, everything else was shared from that stage unchanged.
  const std::vector<std::string>& replanned() const { return replanned_; }

  ecs::World& world() { return world_; }
  const ecs::World& world() const { return world_; }
  const ecs::Schedule& schedule() const { return schedule_; }

  // The frame at `frame` (the sync phase may replace its time from the world's
  // audio_sync::FrameClock), every phase up to `last`: Phase::evaluate for the components,
  // Phase::pose for the models' poses.
  void run(const ecs::FrameTime& frame, ecs::Phase last = ecs::Phase::pose);

  // A context of its own for a caller (a thread) that samples this stage: a copy of the world as
  // it is now. Make it on the thread that owns the stage; then run(context, ...) from any one
  // thread per context, at the same time as other contexts. Throws std::logic_error if a
  // component cannot be copied.
  StageContext make_context() const;
  // The frame at `frame` in `context`'s world: const on the stage. Throws std::invalid_argument
  // for a context made by another stage.
  void run(StageContext& context, const ecs::FrameTime& frame,
           ecs::Phase last = ecs::Phase::pose) const;

 private:
  friend class StageBuilder;
  friend Result<std::unique_ptr<Stage>> build_stage(const scene::Scene& scene,
                                                    std::span<const FamilyPlugin* const> families,
                                                    const StageOptions& options);

  scene::Scene scene_;
  std::vector<music::Score> scores_;
  std::vector<std::vector<ecs::Entity>> note_entities_;  // [score][note]
  std::vector<std::shared_ptr<const model::ModelAsset>> models_;
  std::vector<std::string> model_files_;  // the file each of `models_` came from
  std::vector<ecs::Entity> instances_;
  std::vector<ecs::Entity> performers_;
  std::vector<const FamilyPlugin*> families_;
  std::vector<std::string> notes_;
  std::vector<std::string> replanned_;
  double start_s_ = 0.0;
  double end_s_ = 0.0;
  ecs::World world_;
  ecs::Schedule schedule_;
};

// Poses everything at t_s (seconds of the music): Stage::run up to Phase::pose at that time.
// Deterministic; allocation-free after the first call except inside the systems' own
// (allocation-free) evaluation.
void evaluate_stage(Stage& stage, double t_s);

}  // namespace tutti::stage
