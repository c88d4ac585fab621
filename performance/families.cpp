// SPDX-License-Identifier: MIT
#include <tutti/performance/families.hpp>

#include <array>

#include <tutti/brass/brass_plugin.hpp>
#include <tutti/piano/piano_plugin.hpp>
#include <tutti/stage/stage_builder.hpp>

namespace tutti::performance {

std::span<const stage::FamilyPlugin* const> default_families() {
  static const brass_family::BrassPlugin brass;
  static const piano_family::PianoPlugin piano;
  static const std::array<const stage::FamilyPlugin*, 2> families{&brass, &piano};
  return families;
}

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
