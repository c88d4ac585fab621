// SPDX-License-Identifier: MIT
#pragma once
// A `tutti` subcommand: its name, what it does, its options (each filling a field of the
// command's options) and how it runs. Each <name>_command.cpp describes its own
// (register_<name>_command), commands.cpp lists them, and Commands::run parses the command line
// with CLI11 in one place (command.cpp) and runs the one given.

#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace tutti::cli {

// Runs a parsed subcommand with the options it was given. Returns the exit code
// (exit_codes.hpp).
using CommandRun = std::function<int(std::ostream& out, std::ostream& err)>;

// The fields an option can fill.
using OptionTarget = std::variant<std::string*, std::filesystem::path*, int*, double*,
                                  std::uint64_t*, std::vector<std::filesystem::path>*, bool*>;

struct CommandOption {
  std::string names;  // "--fps", "-o,--output", or a positional argument's name ("SCENE")
  std::string help;
  OptionTarget target;
  bool flag = false;      // takes no value; sets its bool
  bool required = false;  // must be given
};

class Command {
 public:
  Command(std::string name, std::string description)
      : name_(std::move(name)), description_(std::move(description)) {}

  // An option (or positional argument) filling `target`.
  template <typename T>
  Command& option(std::string names, T& target, std::string help) {
    static_assert(std::is_constructible_v<OptionTarget, T*> && !std::is_same_v<T, bool>,
                  "an option fills a string, path, int, double, uint64 or a list of paths");
    options_.push_back({std::move(names), std::move(help), OptionTarget(&target), false, false});
    return *this;
  }
  // A flag: present = true.
  Command& flag(std::string names, bool& target, std::string help);
  // The option added last must be given.
  Command& required();
  // What runs when this command is the one given.
  void on_run(CommandRun run) { run_ = std::move(run); }

  const std::string& name() const { return name_; }
  const std::string& description() const { return description_; }
  const std::vector<CommandOption>& options() const { return options_; }
  int run(std::ostream& out, std::ostream& err) const;

 private:
  std::string name_;
  std::string description_;
  std::vector<CommandOption> options_;
  CommandRun run_;
};

class Commands {
 public:
  // A new subcommand; the reference stays valid as more are added.
  Command& add(std::string name, std::string description);

  // Parses the command line (exactly one subcommand, `--help`, `--version` printing
  // `version`) and runs the subcommand given. A parse error is one line, "error: <what> (see
  // <program> --help)", and kExitBadInput.
  int run(int argc, const char* const* argv, const std::string& description,
          const std::string& version, std::ostream& out, std::ostream& err) const;

 private:
  std::deque<Command> commands_;
};

}  // namespace tutti::cli
