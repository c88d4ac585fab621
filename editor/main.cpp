// SPDX-License-Identifier: MIT
// tutti-editor SCENE [--script FILE]: edit a scene's performance metadata over its 3D view.
#include <CLI/CLI.hpp>
#include <iostream>

#include <tutti/editor/editor_app.hpp>

int main(int argc, char** argv) {
  CLI::App app{"tutti-editor: tweak a scene's performance and see and hear it at once"};
  tutti::editor::EditorOptions options;
  app.add_option("SCENE", options.scene, "scene file (content/scenes/*.json)")->required();
  app.add_option("--script", options.script,
                 "run these actions (editor/script.hpp) instead of waiting for input");
  app.add_option("--assets", options.assets, "folder of the generated .glb assets");
  app.add_option("--soundfont", options.soundfont, "General MIDI .sf2");
  app.add_option("--audio-driver", options.audio_driver,
                 "FluidSynth audio driver (\"simulated\": no sound device)");
  app.add_option("--size", options.size, "window size WxH (default 1600x900)");
  app.add_option("--autosave", options.autosave_s, "seconds between autosaves (default 10)");
  app.add_flag("--validate", options.validate, "Vulkan validation; any message is an error");
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "error: " << e.what() << " (see tutti-editor --help)\n";
    return 2;
  }
  return tutti::editor::run_editor(options, std::cout, std::cerr);
}
