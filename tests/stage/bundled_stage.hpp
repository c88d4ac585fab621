// SPDX-License-Identifier: MIT
#pragma once
// A bundled scene (content/scenes/NAME) staged with the default families, for the stage's tests;
// a failure to load or stage is a test failure and gives nullptr.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string_view>

#include <tutti/performance/families.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/stage/contact_detector.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::stage::test {

inline std::unique_ptr<Stage> stage_bundled_scene(const char* scene_name) {
  const std::filesystem::path scenes = std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes";
  auto scene = scene::load_scene(scenes / scene_name, performance::scene_load_options());
  EXPECT_TRUE(scene) << scene.error().message;
  if (!scene) return nullptr;
  auto stage = performance::build_stage(*scene, {});
  EXPECT_TRUE(stage) << stage.error().message;
  return stage ? std::move(*stage) : nullptr;
}

// Whether the stop is of the kind named `kind` (its host event name).
inline bool stop_is(const Stop& stop, std::string_view kind) { return stop.kind->name == kind; }

}  // namespace tutti::stage::test
