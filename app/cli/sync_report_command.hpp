// SPDX-License-Identifier: MIT
#pragma once
// `tutti sync-report SCENE` — renders the scene's audio, finds the note onsets in it, reads the
// contact times off the animation and prints how far apart they are (sync_report.hpp).
// `--check` makes a missed goal (mean ≤ 5 ms, max ≤ one frame at 60 fps, ≥ 90 % of the
// contacts heard) exit 1.

#include <filesystem>
#include <iosfwd>

#include <tutti/cli/command.hpp>

namespace tutti::cli {

struct SyncReportOptions {
  std::filesystem::path scene;
  std::filesystem::path assets;     // folder of the generated .glb files (default: the build's)
  std::filesystem::path soundfont;  // General MIDI .sf2 (default: audio::find_sound_font)
  std::filesystem::path wav;        // also write the analysed audio here
  double tempo = 1.0;               // practice tempo
  double step_ms = 0.5;             // contact sampling grid
  double tolerance_ms = 50.0;       // furthest match
  int worst = 5;                    // list this many largest offsets
  bool check = false;               // exit 1 when the goal is missed
  bool json = false;                // the figures and every match as JSON on stdout
  bool compensate_attacks = true;   // false: every note at its score time (audio/attack_time.hpp)
};

inline constexpr double kSyncGoalMeanMs = 5.0;
inline constexpr double kSyncGoalMaxMs = 1000.0 / 60.0;
// And the report must have found the sound of nearly every contact.
inline constexpr double kSyncGoalHeard = 0.9;
inline constexpr int kExitSyncGoalMissed = 1;

int run_sync_report(const SyncReportOptions& options, std::ostream& out, std::ostream& err);

// Adds `tutti sync-report` and its options to `tutti`, and its run to `commands`.
void register_sync_report_command(Commands& commands);

}  // namespace tutti::cli
