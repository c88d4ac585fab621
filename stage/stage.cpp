// SPDX-License-Identifier: MIT
#include <tutti/stage/stage.hpp>

#include <cstdlib>
#include <stdexcept>
#include <utility>

#include <tutti/components/note.hpp>
#include <tutti/content/content_dir.hpp>
#include <tutti/stage/stage_builder.hpp>

#ifndef TUTTI_DEFAULT_ASSET_DIR
#define TUTTI_DEFAULT_ASSET_DIR ""
#endif

namespace tutti::stage {

std::filesystem::path default_asset_dir() {
  if (const char* dir = std::getenv("TUTTI_ASSET_DIR"); dir != nullptr && *dir != '\0') {
    return dir;
  }
  if (std::filesystem::path installed = content::installed_data_dir("assets"); !installed.empty()) {
    return installed;
  }
  return TUTTI_DEFAULT_ASSET_DIR;
}

Stage::Stage() = default;
Stage::~Stage() = default;

std::vector<const model::ModelAsset*> Stage::model_list() const {
  std::vector<const model::ModelAsset*> list;
  for (const auto& m : models_) list.push_back(m.get());
  return list;
}

const PlacedModel& Stage::placed(std::size_t instance) const {
  return world_.get<PlacedModel>(instances_[instance]);
}

ecs::Entity Stage::note_entity(std::size_t score, std::size_t index) const {
  if (score >= note_entities_.size() || index >= note_entities_[score].size()) {
    return ecs::Entity::null;
  }
  return note_entities_[score][index];
}

ecs::Entity Stage::find_performer(std::string_view family, std::size_t index) const {
  for (ecs::Entity performer : performers_) {
    const auto* seat = world_.try_get<Seat>(performer);
    if (seat != nullptr && seat->family == family && seat->index == index) return performer;
  }
  return ecs::Entity::null;
}

std::vector<music::Score> Stage::heard_scores() const {
  std::vector<music::Score> heard = scores_;
  for (std::size_t s = 0; s < heard.size(); ++s) {
    std::vector<music::Note>& notes = heard[s].notes;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < notes.size(); ++i) {
      const auto* note = world_.try_get<components::Note>(note_entity(s, i));
      if (note != nullptr) {
        if (note->silent) continue;
        notes[i].onset_s = note->onset_s;
        notes[i].offset_s = note->offset_s;
        notes[i].onset_beats = note->onset_beats;
        notes[i].offset_beats = note->offset_beats;
        notes[i].velocity = note->velocity;
      }
      notes[kept++] = notes[i];
    }
    notes.resize(kept);
  }
  return heard;
}

void Stage::run(const ecs::FrameTime& frame, ecs::Phase last) { schedule_.run(world_, frame, last); }

StageContext::StageContext(const Stage& stage, ecs::World world)
    : stage_(&stage), world_(std::move(world)) {}

const PlacedModel& StageContext::placed(std::size_t instance) const {
  return world_.get<PlacedModel>(stage_->instances()[instance]);
}

StageContext Stage::make_context() const { return StageContext(*this, world_.copy()); }

void Stage::run(StageContext& context, const ecs::FrameTime& frame, ecs::Phase last) const {
  if (context.stage_ != this) {
    throw std::invalid_argument("stage: a sampling context runs only on the stage that made it");
  }
  schedule_.run(context.world_, frame, last);
}

void evaluate_stage(Stage& stage, double t_s) { stage.run({t_s, 0.0}); }

}  // namespace tutti::stage
