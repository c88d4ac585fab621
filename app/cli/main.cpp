// SPDX-License-Identifier: MIT
// The `tutti` command: parse the arguments, run the one subcommand given, return its exit code.
// Each subcommand describes its own options (<name>_command.cpp); commands.cpp lists them.

#include <iostream>
#include <string>
#include <tutti/cli/command.hpp>
#include <tutti/cli/commands.hpp>

int main(int argc, char** argv) {
  tutti::cli::Commands commands;
  tutti::cli::register_commands(commands);
  return commands.run(argc, argv, "tutti: music to animated performances",
                      std::string("tutti ") + TUTTI_VERSION, std::cout, std::cerr);
}
