// SPDX-License-Identifier: MIT
#pragma once
// Every `tutti` subcommand, in the order `tutti --help` lists them (commands.cpp). A new
// subcommand is a <name>_command.hpp/.cpp with its register_<name>_command, and one line there.

#include <tutti/cli/command.hpp>

namespace tutti::cli {

// Adds each subcommand, with its options and its run, to `commands`.
void register_commands(Commands& commands);

}  // namespace tutti::cli
