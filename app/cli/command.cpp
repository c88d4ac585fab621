#include <CLI/CLI.hpp>
#include <ostream>
#include <tutti/cli/command.hpp>
#include <tutti/cli/exit_codes.hpp>

namespace tutti::app {

Command& Command::flag(std::string names, bool& target, std::string help) {
  options_.push_back({std::move(names), std::move(help), OptionTarget(&target), true, false});
  return *this;
}

Command& Command::required() {
  if (!options_.empty()) options_.back().required = true;
  return *this;
}

int Command::run(std::ostream& out, std::ostream& err) const {
  return run_ ? run_(out, err) : kExitBadInput;
}

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
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e, out, err);
  } catch (const CLI::ParseError& e) {
    const std::string program = argc > 0 ? std::filesystem::path(argv[0]).filename().string() : "";
    err << "error: " << e.what() << " (see " << (program.empty() ? "tutti" : program)
        << " --help)\n";
    return kExitBadInput;
  }
  for (const auto& [sub, command] : parsed) {
    if (sub->parsed()) return command->run(out, err);
  }
  return kExitBadInput;
}

}  // namespace tutti::app
