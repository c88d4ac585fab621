// SPDX-License-Identifier: MIT
#pragma once
// `tutti scene new PIECE -o scene.json` — a scene file drafted from a MIDI or MusicXML piece
// (performance/draft_scene.hpp): the pianist, the brass players seated by section, cameras and a
// shot list that follows who plays. The file is checked by loading it as `tutti render` would
// before it is written; an existing file is kept unless --force.

#include <filesystem>
#include <iosfwd>
#include <string>

#include <tutti/cli/command.hpp>

namespace tutti::cli {

struct SceneOptions {
  std::string action;  // "new"
  std::filesystem::path piece;
  std::filesystem::path output;
  bool force = false;
};

int run_scene(const SceneOptions& options, std::ostream& out, std::ostream& err);

void register_scene_command(Commands& commands);

}  // namespace tutti::cli
