// SPDX-License-Identifier: MIT
#include <tutti/performance/families.hpp>

#include <tutti/stage/stage_builder.hpp>

namespace tutti::performance {

scene::LoadOptions scene_load_options(std::filesystem::path content_dir) {
  scene::LoadOptions options;
  options.content_dir = std::move(content_dir);
  for (const stage::FamilyPlugin* family : default_families()) {
    options.sections.push_back(&family->scene_section());
  }
  return options;
}

Result<std::unique_ptr<stage::Stage>> build_stage(const scene::Scene& scene,
                                                  const stage::StageOptions& options) {
  return stage::build_stage(scene, default_families(), options);
}

}  // namespace tutti::performance
