// SPDX-License-Identifier: MIT
#pragma once
// `tutti check-pose SCENE` — the posed skeletons measured frame by frame (performance/
// pose_check.hpp): fingertips on the buttons and keys they press, hands on the instruments, no
// hand inside a head, no piano key left half down. `--check` makes a figure over its limit exit 4.

#include <filesystem>
#include <iosfwd>
#include <string>

#include <tutti/cli/command.hpp>

namespace tutti::cli {

struct CheckPoseOptions {
  std::filesystem::path scene;
  std::filesystem::path assets;  // folder of the generated .glb files (default: the build's)
  std::string seconds;           // A:B, seconds of the music; default: the first 12 s shown
  int fps = 30;
  bool json = false;
  bool check = false;  // exit 4 when a figure is over its limit
};

// Not 1 (an internal error) nor 2 (bad input): the check ran, and a figure is over its limit.
inline constexpr int kExitPoseLimitOver = 4;

int run_check_pose(const CheckPoseOptions& options, std::ostream& out, std::ostream& err);

// Adds `tutti check-pose` and its options to `commands`.
void register_check_pose_command(Commands& commands);

}  // namespace tutti::cli
