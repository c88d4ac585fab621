// SPDX-License-Identifier: MIT
#pragma once
// Building a stage: build_stage() loads the scene's music, makes a Note entity for every note,
// places the floor and lets each family (FamilyPlugin) build its performers through a
// StageBuilder: the content and asset folders, the models (loaded once, shared with the stage
// being re-planned), the placed instances, the performer and note entities, and the messages.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include <tutti/components/performer.hpp>
#include <tutti/core/result.hpp>
#include <tutti/stage/family_plugin.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::stage {

class StageBuilder {
 public:
  StageBuilder(Stage& stage, const StageOptions& options);

  const scene::Scene& scene() const { return stage_.scene_; }
  // The stage being re-planned (StageOptions::reuse_models), or null.
  const Stage* previous() const { return previous_; }
  const std::filesystem::path& content_dir() const { return content_dir_; }
  const std::filesystem::path& asset_dir() const { return asset_dir_; }
  ecs::World& world() { return stage_.world_; }
  const Stage& stage() const { return stage_; }

  // A generated asset, by file name in the asset folder (an error says how to make them).
  Result<std::uint32_t> generated_model(const std::string& file);
  bool generated_model_exists(const std::string& file) const;
  // A user's model, by path.
  Result<std::uint32_t> user_model(const std::filesystem::path& path);
  const model::ModelAsset& model(std::uint32_t index) const { return *stage_.models_[index]; }
  std::shared_ptr<const model::ModelAsset> shared_model(std::uint32_t index) const {
    return stage_.models_[index];
  }

  // A new instance of `model` at `root`, in its rest pose.
  ecs::Entity place(std::uint32_t model, const glm::mat4& root);
  PlacedModel& placed(ecs::Entity instance) { return stage_.world_.get<PlacedModel>(instance); }

  // A new performer entity with `performer` and Seat{family, index}.
  ecs::Entity add_performer(std::string_view family, std::size_t index,
                            components::Performer performer);

  const std::vector<music::Score>& scores() const { return stage_.scores_; }
  ecs::Entity note_entity(std::size_t score, std::size_t index) const {
    return stage_.note_entity(score, index);
  }

  // A planning diagnostic worth showing.
  void note(std::string message) { stage_.notes_.push_back(std::move(message)); }
  // Something planned afresh (not shared from previous()).
  void replanned(std::string what) { stage_.replanned_.push_back(std::move(what)); }

 private:
  Result<std::uint32_t> load(const std::filesystem::path& path, bool generated);
  std::uint32_t add(std::shared_ptr<const model::ModelAsset> model, const std::string& file);

  Stage& stage_;
  const Stage* previous_ = nullptr;
  std::filesystem::path content_dir_;
  std::filesystem::path asset_dir_;
};

// The stage of `scene` with these families, in this order (their systems, planning and models
// in that order).
Result<std::unique_ptr<Stage>> build_stage(const scene::Scene& scene,
                                           std::span<const FamilyPlugin* const> families,
                                           const StageOptions& options);

}  // namespace tutti::stage
