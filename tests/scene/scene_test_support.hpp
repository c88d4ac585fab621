// SPDX-License-Identifier: MIT
#pragma once
// Shared by the scene tests: paths into the source tree and a scratch folder per test.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include <tutti/performance/families.hpp>
#include <tutti/scene/load_scene.hpp>
#include "scratch_dir.hpp"

namespace tutti::scene::test {

inline std::filesystem::path source_dir() { return TUTTI_SOURCE_DIR; }
inline std::filesystem::path scenes_dir() { return source_dir() / "content" / "scenes"; }

// The one-line error of parsing `document` as a scene file "s.json" of content/scenes with the
// default families, or "(loaded)".
inline std::string error_of(const nlohmann::json& document) {
  auto scene = parse_scene(document, "s.json", scenes_dir(), performance::scene_load_options());
  return scene.ok() ? "(loaded)" : scene.error().message;
}

// The scene tests' scratch folders (tests/scratch_dir.hpp).
class ScratchDir : public tutti::test::ScratchDir {
 public:
  ScratchDir() : tutti::test::ScratchDir("tutti_scene_") {}
};

}  // namespace tutti::scene::test
