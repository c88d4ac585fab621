// SPDX-License-Identifier: MIT
#pragma once
// Runs a `tutti` subcommand in-process (its run_* function) and keeps its exit code and what it
// printed, for the command tests.

#include <sstream>
#include <string>

namespace tutti::test {

struct CommandRun {
  int code = -1;
  std::string out;
  std::string err;
};

template <typename Command, typename Options>
CommandRun run_command(Command command, const Options& options) {
  std::ostringstream out;
  std::ostringstream err;
  CommandRun r;
  r.code = command(options, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

}  // namespace tutti::test
