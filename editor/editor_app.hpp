// SPDX-License-Identifier: MIT
#pragma once
// The tutti-editor program: a window with the scene's 3D view (runtime::ScenePlayer), the
// editor's panels over it (editor_ui.hpp through runtime::ImGuiLayer), the session re-planned on
// every edit, periodic autosave, and optionally a --script of actions.

#include <filesystem>
#include <iosfwd>
#include <string>

namespace tutti::editor {

struct EditorOptions {
  std::filesystem::path scene;
  std::filesystem::path script;  // empty: interactive
  std::filesystem::path assets;
  std::filesystem::path soundfont;
  std::string audio_driver;  // FluidSynth driver; "simulated" = none
  std::string size = "1600x900";
  double autosave_s = 10.0;  // seconds between autosaves while there are unsaved edits
  bool validate = false;     // Vulkan validation; any message is an error
};

int run_editor(const EditorOptions& options, std::ostream& out, std::ostream& err);

}  // namespace tutti::editor
