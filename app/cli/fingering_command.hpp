// SPDX-License-Identifier: MIT
#pragma once
// `tutti fingering IN [-o OUT] [--format F] [--mode M] [--lookahead N] [--hand-size NAME]
//                    [--weights FILE_OR_PRESET] [--keep-fingers] [--smoothing NAME] [--plot PNG]
//                    [--plot-seconds A:B]`
// Plans fingering and both hands' paths (systems/piano_performance) for a MIDI, MusicXML or PIG
// file and writes the fingered notes (fingering_output.hpp), a report and optionally a plot.

#include <filesystem>
#include <iosfwd>
#include <string>

#include <tutti/cli/command.hpp>

namespace tutti::cli {

struct FingeringOptions {
  std::filesystem::path input{};
  std::filesystem::path output{};  // empty = listing (or JSON with --format json) on stdout
  std::string format{};            // musicxml | pig | midi | json; empty = from OUT's extension
  std::string mode = "exact";      // exact | lookahead
  int lookahead = 4;
  std::string hand_size{};          // hands.json preset; empty = its default
  std::string weights = "default";  // preset name, or a path to a weights .json file
  bool keep_fingers = false;        // the file's finger marks are pins (else they are ignored)
  // Hand-path smoothing, a spline_motion::SmoothingMode name: monotone_quintic (default), pchip,
  // natural_spline (the paper's; may leave corridors) or none (the taut string).
  std::string smoothing = "monotone_quintic";
  std::filesystem::path plot{};         // PNG piano roll, empty = none
  std::string plot_seconds{};           // "A:B" window for the plot, empty = whole piece
  std::filesystem::path content_dir{};  // empty = piano_model::default_content_dir()
};

// Writes the result, prints the report, or one "error: ..." line to `err`. Returns the exit code.
int run_fingering(const FingeringOptions& options, std::ostream& out, std::ostream& err);

// Adds `tutti fingering` and its options to `tutti`, and its run to `commands`.
void register_fingering_command(Commands& commands);

}  // namespace tutti::cli
