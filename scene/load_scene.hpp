// SPDX-License-Identifier: MIT
#pragma once
// Reading a scene file (format: scene/README.md) into a Scene, strictly: the scene's own keys
// here, each family's players by the SceneSection it registers (scene_section.hpp). Every
// object is checked for unknown keys, every value for its type and range, every referenced file
// for existence, every shot's camera by name, the shot order. Errors are one line,
// "FILE: /json/path: reason", e.g. "quartet.json: /shots/1/camera: no camera named \"wide\" ...".
//
// Score parts are not looked up here (the music is not parsed); load_scene_music does that.

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>
#include <tutti/scene/scene.hpp>
#include <tutti/scene/scene_section.hpp>

namespace tutti::scene {

struct LoadOptions {
  // Where the content the scene is checked against is (instruments, hands, styles); empty:
  // content::default_content_dir() ($TUTTI_CONTENT_DIR, else the content tutti was built with).
  std::filesystem::path content_dir;
  // The families' sections, in the order they read (tutti::performance::scene_load_options()
  // gives those of the default families). A top-level key none of them registers is an error.
  std::vector<const SceneSection*> sections;
};

// Messages use the file's name (not its folder). Missing file: "<path>: no such file"; bad JSON:
// "<name>: not valid JSON (... at byte N)"; empty file: "<name>: empty file".
Result<Scene> load_scene(const std::filesystem::path& path, const LoadOptions& options = {});

// `file_name` is used in messages; relative paths in the scene resolve against `base_dir`.
Result<Scene> parse_scene(const nlohmann::json& document, const std::string& file_name,
                          const std::filesystem::path& base_dir, const LoadOptions& options = {});

// Reads a JSON document with one-line errors naming `path.filename()` (shared with the mapping
// loader): missing file, empty file, not valid JSON (with the byte offset).
Result<nlohmann::json> read_scene_json(const std::filesystem::path& path);

// The index of the part named `wanted` (case-insensitive, whole name) or with that id; -1 if none.
int find_part(const music::Score& score, std::string_view wanted);

// Loads every music file of the scene (tutti::music::load_score) and checks that every part a
// player claims (Scene::part_claims) exists in its music file and that no exclusive part has two
// players, e.g.
// "quintet.json: /performers/1/part: no part "Horn 3" in quintet.musicxml (parts: Horn in F,
// ...)". Returns the scores in Scene::music order.
Result<std::vector<music::Score>> load_scene_music(const Scene& scene);
// The same check on scores already loaded (one per Scene::music entry).
Status check_scene_parts(const Scene& scene, std::span<const music::Score> scores);

}  // namespace tutti::scene
