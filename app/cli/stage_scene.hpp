// SPDX-License-Identifier: MIT
#pragma once
// A scene file loaded and staged (plans, ECS world, models) for a command: its errors are one
// line naming the file (scene::load_scene's own, or "<scene>: <why it cannot be staged>"). A
// music file (MIDI, MusicXML) in place of a scene is drafted into one in memory
// (performance/draft_scene.hpp), exactly as `tutti scene new` would write it.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/scene/scene.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::cli {

// `assets`: the folder of the generated .glb files; empty: the build's or the installation's.
Result<std::unique_ptr<stage::Stage>> stage_scene_file(const std::filesystem::path& scene_file,
                                                       const std::filesystem::path& assets);

}  // namespace tutti::cli
