#include <tutti/cli/command.hpp>

#include <CLI/CLI.hpp>

#include <tutti/cli/exit_codes.hpp>

namespace tutti::app {

void Commands::add(CLI::App* command, CommandRun run) {
  commands_.emplace_back(command, std::move(run));
}

int Commands::run_parsed(std::ostream& out, std::ostream& err) const {
  for (const auto& [command, run] : commands_) {
    if (command->parsed()) return run(out, err);
  }
  return kExitBadInput;
}

}  // namespace tutti::app
