// SPDX-License-Identifier: MIT
#pragma once
// `tutti render SCENE -o OUT.mp4|OUT.png|FOLDER/` — an offline render of a scene (the scene's
// cameras, shot list, lights and output settings) on the Vulkan device (lavapipe when there is no
// GPU). Frame k shows t = start + k / fps exactly, so a slice (--frames A:B) has the pixels the
// full render has for those frames: long renders can be split across machines.

#include <filesystem>
#include <iosfwd>
#include <string>

#include <tutti/cli/command.hpp>

namespace tutti::cli {

struct RenderOptions {
  std::filesystem::path scene;
  std::filesystem::path output;  // .mp4 (H.264, yuv420p, via ffmpeg), .png (--still), or a folder
  std::string size;              // "WxH", default: the scene's output size
  int fps = 0;                   // 0 = the scene's
  int msaa = 0;                  // 0 = the scene's
  double tempo = 1.0;            // practice tempo: 0.5 = half speed, picture and sound alike
  std::string camera;            // a scene camera's name: every frame through it (no shot list)
  std::string shadows;           // "hard" or "soft"; empty = the scene's
  std::string frames;            // "A:B": frames A (inclusive) to B (exclusive)
  std::string seconds;           // "A:B": the frames whose times fall in [A, B)
  std::string still;             // a time in seconds: one frame to a PNG
  std::string device;            // Vulkan device selector (index or name part)
  std::filesystem::path assets;  // folder of the generated .glb files (default: the build's)
  std::filesystem::path wav;     // also write the rendered range's audio here (16-bit PCM)
  std::filesystem::path soundfont;  // General MIDI .sf2 (default: audio::find_sound_font)
  bool audio = true;                // .mp4: an AAC track of the scene's music
  bool lossless = false;            // .mp4: x264 lossless (slices join into an exact render)
  bool validate = false;            // run with the Vulkan validation layer; any message fails
  bool progress = true;             // progress on stderr
};

int run_render(const RenderOptions& options, std::ostream& out, std::ostream& err);

// Adds `tutti render` and its options to `tutti`, and its run to `commands`.
void register_render_command(Commands& commands);

}  // namespace tutti::cli
