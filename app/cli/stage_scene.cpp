// SPDX-License-Identifier: MIT
#include <tutti/cli/stage_scene.hpp>

#include <tutti/performance/draft_scene.hpp>
#include <tutti/performance/families.hpp>

namespace tutti::cli {

Result<std::unique_ptr<stage::Stage>> stage_scene_file(const std::filesystem::path& scene_file,
                                                       const std::filesystem::path& assets) {
  auto scene = performance::load_scene_or_music(scene_file);
  if (!scene) return scene.error();
  stage::StageOptions options;
  options.asset_dir = assets;
  auto staged = performance::build_stage(*scene, options);
  if (!staged) return Error{scene->source + ": " + staged.error().message, staged.error().code};
  return std::move(*staged);
}

}  // namespace tutti::cli
