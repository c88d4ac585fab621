// SPDX-License-Identifier: MIT
#pragma once
// `tutti concat SCENE SLICE.mp4... -o OUT.mp4 [--no-audio] [--soundfont F] [--assets DIR]`
// Joins slices of one render (`tutti render SCENE --frames A:B --no-audio -o slice.mp4`, made on
// as many machines as you like, see docs/render_farm.md) into one video. The video streams are
// copied, not re-encoded: the frames are the slices' exactly (with `tutti render --lossless`,
// exactly a single render's). The sound is rendered once for the whole range from SCENE, not
// per slice. The slices must tile a range of frames (any order on the command line) at one size,
// frame rate, tempo and encoding; each says which frames it holds in its "tutti-slice" tag.

#include <filesystem>
#include <iosfwd>
#include <vector>

#include <tutti/cli/command.hpp>

namespace tutti::cli {

struct ConcatOptions {
  std::filesystem::path scene;  // the scene the slices were rendered from (for the sound)
  std::vector<std::filesystem::path> slices;
  std::filesystem::path output;     // .mp4, written atomically
  std::filesystem::path soundfont;  // General MIDI .sf2 (default: audio::find_sound_font)
  std::filesystem::path assets;     // folder of the generated .glb files (default: the build's)
  bool audio = true;
};

int run_concat(const ConcatOptions& options, std::ostream& out, std::ostream& err);

// Adds `tutti concat` and its options to `tutti`, and its run to `commands`.
void register_concat_command(Commands& commands);

}  // namespace tutti::cli
