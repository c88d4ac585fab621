// SPDX-License-Identifier: MIT
#include <tutti/cli/fit_fingering_command.hpp>

#include <chrono>
#include <cstdio>
#include <memory>
#include <ostream>

#include <tutti/core/exit_codes.hpp>
#include <tutti/cli/weights_option.hpp>
#include <tutti/fingering_planner/weight_fitting.hpp>
#include <tutti/music/load_score.hpp>

namespace tutti::cli {

namespace {

std::string percent(double rate) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f%%", 100.0 * rate);
  return text;
}

}  // namespace

int run_fit_fingering(const FitFingeringOptions& o, std::ostream& out, std::ostream& err) {
  const Fail fail{err};
  if (o.inputs.empty()) return fail("fit-fingering: no annotated files given");
  if (o.output.empty()) return fail("fit-fingering: -o weights.json is required");
  if (o.rounds < 1 || o.rounds > 100) return fail("--rounds: must be within 1..100");

  std::vector<music::Score> annotated;
  int marked = 0;
  for (const auto& input : o.inputs) {
    auto score = music::load_score(input);
    if (!score) return fail(score.error());
    int file_marks = 0;
    for (const auto& note : score->notes) file_marks += note.finger != 0 ? 1 : 0;
    if (file_marks == 0) return fail(input.string() + ": no fingering marks to fit to");
    marked += file_marks;
    annotated.push_back(std::move(*score));
  }

  auto model = load_model_with_weights(o.start, o.hand_size, o.content_dir);
  if (!model) return fail(model.error());

  fingering_planner::FitOptions fit;
  fit.max_rounds = o.rounds;
  fit.hand_preset = o.hand_size;
  if (!o.content_dir.empty()) fit.content_dir = o.content_dir;
  const auto started = std::chrono::steady_clock::now();
  auto result = fingering_planner::fit_weights(annotated, model->weights, fit);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!result) return fail(result.error());

  const Status saved = fingering_planner::save_cost_weights(
      result->weights, o.output,
      "fitted by tutti fit-fingering on " + std::to_string(o.inputs.size()) + " file(s), " +
          std::to_string(marked) + " marked notes, starting from " + o.start);
  if (!saved) return fail(saved.error());

  out << "fitted " << marked << " marked notes in " << o.inputs.size() << " file(s): match "
      << percent(result->match_before) << " -> " << percent(result->match_after) << " ("
      << result->iterations << " rounds, " << result->evaluations << " planner passes, " << seconds
      << " s)\nwrote " << o.output.string() << "\n";
  return kExitOk;
}

void register_fit_fingering_command(Commands& commands) {
  auto options = std::make_shared<FitFingeringOptions>();
  Command& command = commands.add(
      "fit-fingering",
      "Fit the fingering cost weights to annotated pieces (PIG text or MusicXML with fingering "
      "marks) and write them as JSON for `tutti fingering --weights`");
  command.option("FILES", options->inputs, "annotated score files").required();
  command.option("-o,--output", options->output, "weights .json to write").required();
  command.option("--start", options->start,
                 "preset (default, paper) or weights file to start from");
  command.option("--hand-size", options->hand_size, "small, medium or large");
  command.option("--rounds", options->rounds, "coordinate-descent rounds at most (1..100)");
  command.on_run([options](std::ostream& out, std::ostream& err) {
    return run_fit_fingering(*options, out, err);
  });
}

}  // namespace tutti::cli
