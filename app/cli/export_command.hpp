// SPDX-License-Identifier: MIT
#pragma once
// `tutti export SCENE -o performance.glb [--fps N] [--seconds A:B | --frames A:B] [--assets DIR]`
// The scene's characters, hands, piano, instruments and props with the performance baked as glTF
// 2.0 animation (app/export/scene_export.hpp): one clip per performer plus one for the whole
// scene, keys reduced within the stated tolerances. Written atomically (.glb only); prints what
// it wrote.

#include <filesystem>
#include <iosfwd>
#include <string>

#include <tutti/cli/command.hpp>

namespace tutti::cli {

struct ExportOptions {
  std::filesystem::path scene;
  std::filesystem::path output;  // .glb
  int fps = 0;                   // 0 = the scene's
  std::string seconds;           // "A:B": the frames whose times fall in [A, B)
  std::string frames;            // "A:B": frames A (inclusive) to B (exclusive)
  std::filesystem::path assets;  // folder of the generated .glb files (default: the build's)
  bool json_summary = false;     // the summary as one JSON object instead of text
};

int run_export(const ExportOptions& options, std::ostream& out, std::ostream& err);

// Adds `tutti export` and its options to `tutti`, and its run to `commands`.
void register_export_command(Commands& commands);

}  // namespace tutti::cli
