#pragma once
// A `tutti` subcommand is its CLI11 subcommand, whose options fill the command's options, and a
// run that calls run_<name> with them. Each <name>_command.cpp registers its own
// (register_<name>_command), commands.cpp lists them and main.cpp runs the one that was parsed.

#include <functional>
#include <iosfwd>
#include <utility>
#include <vector>

namespace CLI {
class App;
}  // namespace CLI

namespace tutti::app {

// Runs a parsed subcommand with the options it was given. Returns the exit code
// (exit_codes.hpp).
using CommandRun = std::function<int(std::ostream& out, std::ostream& err)>;

class Commands {
 public:
  // `command` is a subcommand of the app that will be parsed; `run` runs it.
  void add(CLI::App* command, CommandRun run);
  // Runs the subcommand that was parsed (the first, should there be several); kExitBadInput
  // when none was.
  int run_parsed(std::ostream& out, std::ostream& err) const;

 private:
  std::vector<std::pair<CLI::App*, CommandRun>> commands_;
};

}  // namespace tutti::app
