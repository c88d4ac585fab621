// SPDX-License-Identifier: MIT
// tutti-stream-report: its own program (not a `tutti` subcommand) so the streaming figures can
// be re-made without touching the main command line.
#include <CLI/CLI.hpp>
#include <iostream>

#include <tutti/cli/stream_report_command.hpp>

int main(int argc, char** argv) {
  CLI::App app{
      "The streaming fingering planner against the exact one: per file and lookahead, the share "
      "of notes with the exact plan's finger and the cost ratio (Markdown table)"};
  tutti::cli::StreamReportOptions options;
  app.add_option("FILES", options.inputs, "scores (MusicXML, MIDI, PIG)")->required();
  app.add_option("--lookahead", options.lookaheads, "future events each decision waits for")
      ->delimiter(',');
  app.add_option("--weights", options.weights,
                 "cost weights preset (content/piano/fingering/NAME.json)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  return tutti::cli::run_stream_report(options, std::cout, std::cerr);
}
