// SPDX-License-Identifier: MIT
#include <tutti/stage/stage_builder.hpp>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include <tutti/audio_sync/audio_sync_system.hpp>
#include <tutti/components/note.hpp>
#include <tutti/content/content_dir.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/note_sounding/note_sounding_system.hpp>

namespace tutti::stage {

StageBuilder::StageBuilder(Stage& stage, const StageOptions& options)
    : stage_(stage),
      previous_(options.reuse_models),
      content_dir_(options.content_dir.empty() ? content::default_content_dir()
                                               : options.content_dir),
      asset_dir_(options.asset_dir.empty() ? default_asset_dir() : options.asset_dir) {}

Result<std::uint32_t> StageBuilder::generated_model(const std::string& file) {
  return load(asset_dir_ / file, true);
}

bool StageBuilder::generated_model_exists(const std::string& file) const {
  return std::filesystem::exists(asset_dir_ / file);
}

Result<std::uint32_t> StageBuilder::user_model(const std::filesystem::path& path) {
  return load(path, false);
}

Result<std::uint32_t> StageBuilder::load(const std::filesystem::path& path, bool generated) {
  const std::string file = path.string();
  for (std::size_t i = 0; i < stage_.model_files_.size(); ++i) {
    if (stage_.model_files_[i] == file) return static_cast<std::uint32_t>(i);
  }
  if (previous_ != nullptr) {
    for (std::size_t i = 0; i < previous_->model_files_.size(); ++i) {
      if (previous_->model_files_[i] == file) return add(previous_->models_[i], file);
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

std::uint32_t StageBuilder::add(std::shared_ptr<const model::ModelAsset> model,
                                const std::string& file) {
  stage_.models_.push_back(std::move(model));
  stage_.model_files_.push_back(file);
  return static_cast<std::uint32_t>(stage_.models_.size() - 1);
}

ecs::Entity StageBuilder::place(std::uint32_t model, const glm::mat4& root) {
  PlacedModel placed;
  placed.model = model;
  placed.asset = stage_.models_[model];
  placed.root = root;
  placed.pose = model::rest_pose(*placed.asset);
  const ecs::Entity instance = stage_.world_.create();
  stage_.world_.add<PlacedModel>(instance, std::move(placed));
  stage_.instances_.push_back(instance);
  return instance;
}

ecs::Entity StageBuilder::add_performer(std::string_view family, std::size_t index,
                                        components::Performer performer) {
  const ecs::Entity entity = stage_.world_.create();
  stage_.world_.add<components::Performer>(entity, std::move(performer));
  stage_.world_.add<Seat>(entity, Seat{std::string(family), index, {}, {}});
  stage_.performers_.push_back(entity);
  return entity;
}

namespace {

// One Note entity per note of every score, as written; the families claim theirs (performer,
// hand, finger) and change what they play differently (a breath's early release, the keys'
// timing).
void spawn_notes(Stage& stage, ecs::World& world, std::vector<std::vector<ecs::Entity>>& out) {
  out.resize(stage.scores().size());
  for (std::size_t s = 0; s < stage.scores().size(); ++s) {
    const music::Score& score = stage.scores()[s];
    out[s].reserve(score.notes.size());
    for (std::size_t i = 0; i < score.notes.size(); ++i) {
      const music::Note& written = score.notes[i];
      components::Note note;
      note.pitch = written.pitch;
      note.onset_s = written.onset_s;
      note.offset_s = written.offset_s;
      note.onset_beats = written.onset_beats;
      note.offset_beats = written.offset_beats;
      note.velocity = written.velocity;
      note.written_onset_s = written.onset_s;
      note.written_offset_s = written.offset_s;
      note.score = static_cast<std::int32_t>(s);
      note.score_index = static_cast<std::int32_t>(i);
      const ecs::Entity entity = world.create();
      world.add<components::Note>(entity, note);
      out[s].push_back(entity);
    }
  }
}

}  // namespace

Result<std::unique_ptr<Stage>> build_stage(const scene::Scene& scene,
                                           std::span<const FamilyPlugin* const> families,
                                           const StageOptions& options) {
  auto stage = std::make_unique<Stage>();
  stage->scene_ = scene;
  stage->families_.assign(families.begin(), families.end());
  double music_end = 0.0;
  for (const std::filesystem::path& file : scene.music) {
    auto score = music::load_score(file);
    if (!score) return score.error();
    music_end = std::max(music_end, score->duration_s());
    stage->scores_.push_back(std::move(*score));
  }
  spawn_notes(*stage, stage->world_, stage->note_entities_);

  // The frame: the clock, the notes, then each family's systems in family order.
  audio_sync::register_audio_sync(stage->schedule_);
  note_sounding::register_note_sounding(stage->schedule_);
  for (const FamilyPlugin* family : families) family->add_systems(stage->schedule_);
  // Two writers of one component in a phase must be ordered (ecs::Schedule::check).
  if (const std::vector<std::string> problems = stage->schedule_.check(); !problems.empty()) {
    std::string listed;
    for (const std::string& problem : problems) listed += (listed.empty() ? "" : "; ") + problem;
    return Error{"the frame's schedule: " + listed};
  }

  StageBuilder builder(*stage, options);
  auto floor = builder.generated_model("stage.glb");
  if (!floor) return floor.error();
  builder.placed(builder.place(*floor, glm::mat4(1.0f))).casts_shadows = false;
  for (const FamilyPlugin* family : families) {
    if (Status s = family->build(builder); !s) return s.error();
  }
  stage->start_s_ = scene.output.start_s;
  stage->end_s_ = scene.output.end_s ? *scene.output.end_s : music_end + 1.0;
  return stage;
}

}  // namespace tutti::stage
