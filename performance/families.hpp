// SPDX-License-Identifier: MIT
#pragma once
// The instrument families tutti stages, in the order of plugins/CMakeLists.txt's list of
// families (one line each; default_families() is generated from it). A program with families
// of its own passes its list to stage::build_stage and performance::draft_scene.

#include <filesystem>
#include <memory>
#include <span>

#include <tutti/core/result.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/scene/scene.hpp>
#include <tutti/stage/family_plugin.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::performance {

std::span<const stage::FamilyPlugin* const> default_families();

// How to read a scene file with the default families' sections (each family's players under
// its own keys): scene::load_scene(path, scene_load_options()). `content_dir` as in
// scene::LoadOptions.
scene::LoadOptions scene_load_options(std::filesystem::path content_dir = {});

// stage::build_stage with default_families().
Result<std::unique_ptr<stage::Stage>> build_stage(const scene::Scene& scene,
                                                  const stage::StageOptions& options = {});

}  // namespace tutti::performance
