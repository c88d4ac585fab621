// SPDX-License-Identifier: MIT
#pragma once
// `tutti info FILE [--json]`: what is in a score file.
// `tutti info --schedule SCENE`: the frame of a staged scene — each phase of the schedule with its
// systems in run order and what each reads and writes, then the entities by component.

#include <filesystem>
#include <iosfwd>

#include <tutti/cli/command.hpp>

namespace tutti::cli {

struct InfoOptions {
  std::filesystem::path file;
  bool json = false;
  bool schedule = false;  // FILE is a scene: print its stage's schedule
};

// Prints the report to `out`, or one "error: ..." line to `err`. Returns the exit code.
int run_info(const InfoOptions& options, std::ostream& out, std::ostream& err);

// Adds `tutti info` and its options to `tutti`, and its run to `commands`.
void register_info_command(Commands& commands);

}  // namespace tutti::cli
