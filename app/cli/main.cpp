// The `tutti` command: parse the arguments, run the one subcommand given, return its exit code.
// Each subcommand registers its own options (<name>_command.cpp); commands.cpp lists them.

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include <tutti/cli/command.hpp>
#include <tutti/cli/commands.hpp>
#include <tutti/cli/exit_codes.hpp>

int main(int argc, char** argv) {
  CLI::App app{"tutti: music to animated performances"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("tutti ") + TUTTI_VERSION);
  tutti::app::Commands commands;
  tutti::app::register_commands(app, commands);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "error: " << e.what() << " (see tutti --help)\n";
    return tutti::app::kExitBadInput;
  }
  return commands.run_parsed(std::cout, std::cerr);
}
