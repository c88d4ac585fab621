// SPDX-License-Identifier: MIT
#pragma once
// `tutti play SCENE` — the scene performing live in a window: the picture on the Vulkan device
// (lavapipe when there is no GPU), the sound through FluidSynth's audio driver (a simulated,
// silent device when there is no sound card), the clock from the sound. Keys and mouse as in
// app/runtime/input_bindings.hpp; the title bar and stdout show the time, camera, tempo and
// loop. Frames the device cannot draw in time are dropped: the music never slows.

#include <filesystem>
#include <iosfwd>
#include <string>

#include <tutti/cli/command.hpp>

namespace tutti::cli {

struct PlayOptions {
  std::filesystem::path scene;
  double tempo = 1.0;                // practice tempo, 0.1..4
  std::string camera;                // a scene camera's name (default: the shot list)
  std::string start;                 // seconds of the music to start at (default: the scene's)
  std::string loop;                  // "A:B": play [A, B) over and over
  std::filesystem::path soundfont;   // General MIDI .sf2 (default: audio::find_sound_font)
  std::filesystem::path assets;      // folder of the generated .glb files
  std::string audio_driver;          // FluidSynth driver; "simulated": no device
  std::string device;                // Vulkan device selector (index or name part)
  int frames = 0;                    // > 0: quit after this many frames (tests, automation)
  std::string size;                  // window "WxH" (default: the scene's output size)
  // "draft" (1 sample per pixel, hard shadows, the 3D view at a dynamic scale), "full" (the
  // scene's settings, full size) or "auto": draft on a CPU device (lavapipe), full on a GPU.
  std::string quality = "auto";
  // The 3D view's share of the window per axis: "auto" (dynamic in draft, 1 in full) or a fixed
  // number in [0.25, 1].
  std::string render_scale = "auto";
  bool stats = false;  // show the statistics (F3) from the start
  std::filesystem::path screenshot;  // .png: the last frame
  bool validate = false;             // Vulkan validation layer; any message fails
  // Live input (play_live.hpp): the pianist plays what comes in instead of the score.
  std::string midi_in;          // ALSA sequencer: "auto", "none", "client:port" or a name
  bool keyboard_piano = false;  // the computer keyboard as a piano (keyboard_piano.hpp)
};

int run_play(const PlayOptions& options, std::ostream& out, std::ostream& err);

// Adds `tutti play` and its options to `tutti`, and its run to `commands`.
void register_play_command(Commands& commands);

}  // namespace tutti::cli
