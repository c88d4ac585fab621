// SPDX-License-Identifier: MIT
#include <CLI/CLI.hpp>
#include <exception>
#include <ostream>
#include <tutti/cli/command.hpp>
#include <tutti/core/exit_codes.hpp>
#include <tutti/core/did_you_mean.hpp>

namespace tutti::cli {

Command& Command::flag(std::string names, bool& target, std::string help) {
  options_.push_back({std::move(names), std::move(help), OptionTarget(&target), true, false});
  return *this;
}

Command& Command::required() {
  if (!options_.empty()) options_.back().required = true;
  return *this;
}

int Command::run(std::ostream& out, std::ostream& err) const {
  if (!run_) return kExitInternal;
  // Errors are values; an exception reaching here is tutti's own fault (or out of memory).
  try {
    return run_(out, err);
  } catch (const std::exception& e) {
    err << "error: internal error in tutti " << name_ << ": " << e.what()
        << " (please report it)\n";
  } catch (...) {
    err << "error: internal error in tutti " << name_ << " (please report it)\n";
  }
  return kExitInternal;
}

namespace {

// The option names of a command, without dashes' variants: "-o,--output" gives "-o", "--output".
std::vector<std::string> option_names(const Command& command) {
  std::vector<std::string> names;
  for (const CommandOption& option : command.options()) {
    std::string rest = option.names;
    while (!rest.empty()) {
      const std::size_t comma = rest.find(',');
      const std::string name = rest.substr(0, comma);
      if (name.starts_with("-")) names.push_back(name);
      rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
    }
  }
  return names;
}

// " (did you mean "--frames"?)" for an unknown option among a command's.
std::string suggest_option(const std::string& typed, const Command& command) {
  const std::vector<std::string> names = option_names(command);
  std::vector<std::string_view> views(names.begin(), names.end());
  return did_you_mean(typed, views);
}

}  // namespace

Command& Commands::add(std::string name, std::string description) {
  return commands_.emplace_back(std::move(name), std::move(description));
}

int Commands::run(int argc, const char* const* argv, const std::string& description,
                  const std::string& version, std::ostream& out, std::ostream& err) const {
  CLI::App app{description};
  app.require_subcommand(1);
  app.set_version_flag("--version", version);
  std::vector<std::pair<CLI::App*, const Command*>> parsed;
  for (const Command& command : commands_) {
    CLI::App* sub = app.add_subcommand(command.name(), command.description());
    for (const CommandOption& option : command.options()) {
      CLI::Option* added = std::visit(
          [&](auto* target) -> CLI::Option* {
            using T = std::remove_pointer_t<decltype(target)>;
            if constexpr (std::is_same_v<T, bool>) {
              return sub->add_flag(option.names, *target, option.help);
            } else {
              return sub->add_option(option.names, *target, option.help);
            }
          },
          option.target);
      if (option.required) added->required();
    }
    parsed.emplace_back(sub, &command);
  }
  const std::string program =
      argc > 0 && argv[0] != nullptr ? std::filesystem::path(argv[0]).filename().string() : "";
  const std::string see = " (see " + (program.empty() ? std::string("tutti") : program) + " --help)";
  // A first word that is no command: name the closest one.
  if (argc > 1 && argv[1] != nullptr && argv[1][0] != '-') {
    const std::string typed = argv[1];
    std::vector<std::string_view> names;
    bool known = false;
    for (const Command& command : commands_) {
      names.push_back(command.name());
      known = known || command.name() == typed;
    }
    if (!known) {
      err << "error: \"" << typed << "\" is not a command" << did_you_mean(typed, names) << see
          << "\n";
      return kExitBadInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e, out, err);
  } catch (const CLI::ExtrasError& e) {
    // An option the command does not have: suggest one it has.
    std::string suggestion;
    for (const auto& [sub, command] : parsed) {
      if (!sub->parsed()) continue;
      for (const std::string& extra : sub->remaining()) {
        if (extra.starts_with("-")) {
          suggestion = suggest_option(extra.substr(0, extra.find('=')), *command);
          if (!suggestion.empty()) break;
        }
      }
    }
    err << "error: " << e.what() << suggestion << see << "\n";
    return kExitBadInput;
  } catch (const CLI::ParseError& e) {
    err << "error: " << e.what() << see << "\n";
    return kExitBadInput;
  }
  for (const auto& [sub, command] : parsed) {
    if (sub->parsed()) return command->run(out, err);
  }
  return kExitBadInput;
}

}  // namespace tutti::cli
