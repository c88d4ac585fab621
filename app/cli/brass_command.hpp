// SPDX-License-Identifier: MIT
#pragma once
// `tutti brass FILE [--part NAME|INDEX] [--voice N] [--instrument ID] [--json]`: how every brass
// player of a score plays — per note the sounding and written pitch, valves or slide position
// (and partial), whether an alternate was chosen, the mouth tension; the breath events; notes
// out of range.

#include <filesystem>
#include <iosfwd>
#include <string>

#include <tutti/cli/command.hpp>

namespace tutti::cli {

struct BrassOptions {
  std::filesystem::path file;
  std::string part;        // name (case-insensitive, whole or part) or 1-based index; "" = all
  int voice = 0;           // 1-based player within the part; 0 = every voice
  std::string instrument;  // instrument id (content/instruments/<id>.json); "" = detect
  bool json = false;
};

int run_brass(const BrassOptions& options, std::ostream& out, std::ostream& err);

// Adds `tutti brass` and its options to `tutti`, and its run to `commands`.
void register_brass_command(Commands& commands);

}  // namespace tutti::cli
