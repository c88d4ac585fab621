// SPDX-License-Identifier: MIT
#include <tutti/cli/perform_command.hpp>

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include <tutti/core/exit_codes.hpp>
#include <tutti/core/file_io.hpp>
#include <tutti/finger_motion/finger_motion_params.hpp>
#include <tutti/key_action/humane_performance.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/music/midi/midi_writer.hpp>
#include <tutti/piano_model/content_dir.hpp>
#include <tutti/piano_performance/performance_plan.hpp>

namespace tutti::cli {
namespace {

nlohmann::json notes_json(const music::Score& score,
                          const std::vector<key_action::PlayedNote>& played) {
  nlohmann::json notes = nlohmann::json::array();
  for (std::size_t i = 0; i < played.size(); ++i) {
    const key_action::PlayedNote& p = played[i];
    if (p.outcome == key_action::KeyOutcome::not_played) continue;
    nlohmann::json note = {{"note", i},
                           {"key", p.key},
                           {"written_onset_s", score.notes[i].onset_s},
                           {"written_velocity", score.notes[i].velocity},
                           {"outcome", key_action::outcome_name(p.outcome)},
                           {"key_speed_mm_s", p.key_speed_mm_s}};
    if (p.outcome == key_action::KeyOutcome::sounded) {
      note["onset_s"] = p.onset_s;
      note["offset_s"] = p.offset_s;
      note["velocity"] = p.velocity;
    }
    notes.push_back(std::move(note));
  }
  return notes;
}

}  // namespace

int run_perform(const PerformOptions& o, std::ostream& out, std::ostream& err) {
  const Fail fail{err};
  if (!o.output.empty() && o.style == "all") {
    return fail(
        Error{"--style all: reports every style; give one style to write " + o.output.string()});
  }
  if (!o.output.empty()) {
    const std::string ext = o.output.extension().string();
    if (ext != ".mid" && ext != ".midi") {
      return fail(Error{o.output.string() + ": the output is a MIDI file (.mid)"});
    }
  }
  const std::filesystem::path content =
      o.content_dir.empty() ? piano_model::default_content_dir() : o.content_dir;
  auto styles = key_action::load_styles(key_action::styles_path(content));
  if (!styles) return fail(styles.error());
  std::vector<key_action::PerformanceStyle> chosen;
  if (o.style == "all") {
    chosen = styles->styles;
  } else {
    auto style = styles->find(o.style);
    if (!style) return fail(Error{"--style: " + style.error().message});
    chosen.push_back(std::move(*style));
  }
  auto action = key_action::load_key_action(key_action::key_action_path(content));
  if (!action) return fail(action.error());
  auto params =
      finger_motion::load_finger_motion_params(finger_motion::finger_motion_params_path(content));
  if (!params) return fail(params.error());
  auto score = music::load_score(o.input);
  if (!score) return fail(score.error());
  for (music::Note& n : score->notes) n.finger = 0;
  auto model = fingering_planner::load_fingering_model("default", o.hand_size, content);
  if (!model) return fail(model.error());
  auto plan = piano_performance::plan_performance(*score, *model);
  if (!plan) return fail(plan.error());

  nlohmann::json report = nlohmann::json::object();
  for (const key_action::PerformanceStyle& style : chosen) {
    key_action::HumaneInputs in;
    in.score = &*score;
    in.fingering = &plan->fingering;
    in.right_path = &plan->right_path;
    in.left_path = &plan->left_path;
    in.keyboard = &model->keyboard;
    in.hand_model = &model->hand;
    in.params = &*params;
    in.action = &*action;
    in.style = &style;
    in.seed = o.seed;
    auto performed = key_action::perform(in);
    if (!performed) return fail(performed.error());
    if (!o.json) out << style.name << ": " << key_action::format_report(performed->report) << "\n";
    if (!o.output.empty()) {
      const music::Score heard = key_action::performed_score(*score, performed->played);
      const std::vector<std::uint8_t> bytes = music::write_midi(heard);
      if (Status s = write_file_atomically(o.output, std::string(bytes.begin(), bytes.end())); !s) {
        return fail(s.error());
      }
    }
    if (o.json) {
      const key_action::PerformanceReport& r = performed->report;
      report[style.name] = {{"notes", r.notes},
                            {"sounded", r.sounded},
                            {"too_soft", r.too_soft},
                            {"not_reset", r.not_reset},
                            {"onset_mean_ms", r.onset_mean_ms},
                            {"onset_mean_abs_ms", r.onset_mean_abs_ms},
                            {"onset_std_ms", r.onset_std_ms},
                            {"onset_max_abs_ms", r.onset_max_abs_ms},
                            {"velocity_min", r.velocity_min},
                            {"velocity_max", r.velocity_max},
                            {"velocity_mean", r.velocity_mean},
                            {"velocity_std", r.velocity_std},
                            {"played", notes_json(*score, performed->played)}};
    }
  }
  if (o.json) out << report.dump(1) << "\n";
  return kExitOk;
}

void register_perform_command(Commands& commands) {
  auto options = std::make_shared<PerformOptions>();
  Command& command = commands.add(
      "perform",
      "Play a MIDI or MusicXML file on the simulated piano in a performance style: the notes as "
      "the keys sound them (escapement time, velocity from key speed), written as MIDI, and a "
      "report of onset deviation, velocity spread and missed notes");
  command.option("IN", options->input, "score file").required();
  command.option("-o,--output", options->output, "write the performed notes (.mid)");
  command.option("--style", options->style,
                 "precise (default), gentle, beginner, or all (report only)");
  command.option("--seed", options->seed, "motor-noise seed (default 1)");
  command.option("--hand-size", options->hand_size, "small, medium or large");
  command.flag("--json", options->json,
               "print the report and every note's outcome as JSON (instead of text)");
  command.on_run(
      [options](std::ostream& out, std::ostream& err) { return run_perform(*options, out, err); });
}

}  // namespace tutti::cli
