// SPDX-License-Identifier: MIT
#pragma once
// `tutti fit-fingering FILES... -o weights.json [--start PRESET_OR_FILE] [--hand-size NAME]
//                      [--rounds N]`
// Fits the fingering cost weights to annotated pieces (PIG text, MusicXML with fingering marks,
// MIDI written by `tutti fingering`) by coordinate descent on the exact planner's agreement with
// the marks, and writes them in the schema of content/piano/fingering/*.json, for
// `tutti fingering --weights weights.json`.

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include <tutti/cli/command.hpp>

namespace tutti::cli {

struct FitFingeringOptions {
  std::vector<std::filesystem::path> inputs;
  std::filesystem::path output;
  std::string start = "default";  // preset or weights file to start from
  std::string hand_size{};
  int rounds = 8;
  std::filesystem::path content_dir{};  // empty = piano_model::default_content_dir()
};

// Prints the match rate before/after and the time taken; one "error: ..." line on failure.
int run_fit_fingering(const FitFingeringOptions& options, std::ostream& out, std::ostream& err);

// Adds `tutti fit-fingering` and its options to `tutti`, and its run to `commands`.
void register_fit_fingering_command(Commands& commands);

}  // namespace tutti::cli
