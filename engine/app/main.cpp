// The `tutti` command: parse arguments, call one subcommand, return its exit code. Each
// subcommand lives in its own <name>_command.cpp.

#include <CLI/CLI.hpp>
#include <iostream>

#include "app/exit_codes.hpp"
#include "app/info_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"tutti: music to animated performances"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("tutti ") + TUTTI_VERSION);

  tutti::app::InfoOptions info;
  CLI::App* info_cmd = app.add_subcommand("info",
                                          "Parts, notes, duration, tempo and ranges of a "
                                          "MIDI, MusicXML (.xml/.musicxml/.mxl) or PIG file");
  info_cmd->add_option("FILE", info.file, "score file")->required();
  info_cmd->add_flag("--json", info.json, "print JSON instead of text");

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "error: " << e.what() << " (see tutti --help)\n";
    return tutti::app::kExitBadInput;
  }

  if (*info_cmd) return tutti::app::run_info(info, std::cout, std::cerr);
  return tutti::app::kExitBadInput;
}
