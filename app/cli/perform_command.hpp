// SPDX-License-Identifier: MIT
#pragma once
// `tutti perform IN [-o OUT.mid] [--style NAME|all] [--seed N] [--hand-size NAME]`
// Plays a MIDI or MusicXML file on the simulated piano: fingering and hand paths
// (systems/piano_performance), strokes in a performance style, the finger motion, and the keys
// that motion presses (systems/key_action). Writes the notes as the keys sounded them to OUT
// (a Standard MIDI File) and prints a report per style: onset deviation from the written times
// (mean, std, max ms), velocity spread, missed notes.

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>

#include <tutti/cli/command.hpp>

namespace tutti::cli {

struct PerformOptions {
  std::filesystem::path input;
  std::filesystem::path output;   // .mid; empty = report only
  std::string style = "precise";  // a content/piano/styles.json style, or "all" (report only)
  std::uint64_t seed = 1;
  std::string hand_size;              // hands.json preset; empty = its default
  std::filesystem::path content_dir;  // empty = piano_model::default_content_dir()
  bool json = false;  // the report and per-note outcomes as JSON on stdout, instead of text
};

int run_perform(const PerformOptions& options, std::ostream& out, std::ostream& err);

// Adds `tutti perform` and its options to `tutti`, and its run to `commands`.
void register_perform_command(Commands& commands);

}  // namespace tutti::cli
