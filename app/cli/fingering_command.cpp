// SPDX-License-Identifier: MIT
#include <tutti/cli/fingering_command.hpp>

#include <memory>
#include <optional>
#include <ostream>

#include <tutti/core/exit_codes.hpp>
#include <tutti/cli/fingering_output.hpp>
#include <tutti/cli/fingering_report.hpp>
#include <tutti/cli/piano_roll_plot.hpp>
#include <tutti/cli/weights_option.hpp>
#include <tutti/core/file_io.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/music/musicxml/musicxml_fingering_writer.hpp>
#include <tutti/music/pig/pig_format.hpp>
#include <tutti/piano_performance/performance_plan.hpp>

namespace tutti::cli {
namespace {

namespace fs = std::filesystem;

enum class OutFormat { listing, json, pig, midi, musicxml };

Result<OutFormat> parse_format(const std::string& name) {
  if (name == "json") return OutFormat::json;
  if (name == "pig") return OutFormat::pig;
  if (name == "midi") return OutFormat::midi;
  if (name == "musicxml") return OutFormat::musicxml;
  return Error{"--format: unknown format '" + name + "' (musicxml, pig, midi or json)"};
}

// --format wins; else OUT's extension; no OUT = a listing on stdout.
Result<OutFormat> output_format(const FingeringOptions& o) {
  if (!o.format.empty()) return parse_format(o.format);
  if (o.output.empty()) return OutFormat::listing;
  const std::string ext = o.output.extension().string();
  if (ext == ".musicxml" || ext == ".xml") return OutFormat::musicxml;
  if (ext == ".txt" || ext == ".pig") return OutFormat::pig;
  if (ext == ".mid" || ext == ".midi") return OutFormat::midi;
  if (ext == ".json") return OutFormat::json;
  return Error{o.output.string() + ": unknown output extension '" + ext +
               "' (.musicxml/.xml, .txt/.pig, .mid, .json, or give --format)"};
}

Result<fingering_planner::PlannerMode> parse_mode(const std::string& mode) {
  if (mode == "exact") return fingering_planner::PlannerMode::exact;
  if (mode == "lookahead") return fingering_planner::PlannerMode::lookahead;
  return Error{"--mode: unknown mode '" + mode + "' (exact or lookahead)"};
}

Result<spline_motion::SmoothingMode> parse_smoothing(const std::string& name) {
  if (const auto mode = spline_motion::smoothing_mode_from_string(name)) return *mode;
  return Error{"--smoothing: unknown smoothing '" + name +
               "' (monotone_quintic, pchip, natural_spline or none)"};
}

Result<fingering_planner::FingeringModel> load_model(const FingeringOptions& o) {
  return load_model_with_weights(o.weights, o.hand_size, o.content_dir);
}

Status write_output(OutFormat format, const FingeringOptions& o, const music::Score& fingered,
                    const piano_performance::PianoPerformancePlan& plan, std::ostream& out) {
  switch (format) {
    case OutFormat::listing:
      out << fingering_listing(fingered);
      return Status::success();
    case OutFormat::json:
      if (o.output.empty()) {
        out << fingering_json(fingered, plan.report);
        return Status::success();
      }
      return write_file_atomically(o.output, fingering_json(fingered, plan.report));
    case OutFormat::pig:
      if (o.output.empty()) {
        out << music::write_pig(fingered);
        return Status::success();
      }
      return write_file_atomically(o.output, music::write_pig(fingered));
    case OutFormat::midi: {
      const std::vector<std::uint8_t> bytes = fingering_midi(fingered);
      return write_file_atomically(o.output, std::string(bytes.begin(), bytes.end()));
    }
    case OutFormat::musicxml: {
      auto original = read_file_bytes(o.input);
      if (!original) return original.error();
      auto xml = music::add_fingering_marks(*original, o.input.string(), fingered);
      if (!xml) return xml.error();
      if (o.output.empty()) {
        out << *xml;
        return Status::success();
      }
      return write_file_atomically(o.output, *xml);
    }
  }
  return Error{"unreachable output format"};
}

}  // namespace

int run_fingering(const FingeringOptions& o, std::ostream& out, std::ostream& err) {
  const Fail fail{err};
  // Usage first, so a typo fails before any planning.
  const auto format = output_format(o);
  if (!format) return fail(format.error());
  const auto mode = parse_mode(o.mode);
  if (!mode) return fail(mode.error());
  if (o.lookahead < 1) return fail(Error{"--lookahead: must be at least 1"});
  const auto smoothing = parse_smoothing(o.smoothing);
  if (!smoothing) return fail(smoothing.error());
  std::optional<PlotWindow> window;
  if (!o.plot_seconds.empty()) {
    auto parsed = parse_plot_window(o.plot_seconds);
    if (!parsed) return fail(parsed.error());
    window = *parsed;
  }

  if (*format == OutFormat::midi && o.output.empty()) {
    return fail(Error{"--format midi: needs -o OUT (MIDI is binary)"});
  }

  auto score = music::load_score(o.input);
  if (!score) return fail(score.error());
  if (*format == OutFormat::musicxml) {
    auto bytes = read_file_bytes(o.input);
    const auto in_format = bytes ? music::detect_score_format(*bytes, o.input) : std::nullopt;
    if (in_format != music::ScoreFormat::musicxml) {
      return fail(Error{(o.output.empty() ? o.input : o.output).string() +
                        ": MusicXML output needs a MusicXML input (" + o.input.string() + " is " +
                        (in_format ? music::format_name(*in_format) : "unknown") + ")"});
    }
  }
  // The file's finger marks are pins only when asked; otherwise plan from scratch. A MIDI file
  // tutti wrote carries them as lyric labels (fingering_output.hpp).
  if (o.keep_fingers) {
    apply_finger_labels(*score);
  } else {
    for (music::Note& n : score->notes) {
      n.finger = 0;
      n.finger_substitute = 0;
    }
  }
  auto model = load_model(o);
  if (!model) return fail(model.error());

  piano_performance::PerformanceOptions options;
  options.fingering.mode = *mode;
  options.fingering.lookahead = o.lookahead;
  options.fingering.pins_from_marks = o.keep_fingers;
  options.path.smoothing = *smoothing;
  auto plan = piano_performance::plan_performance(*score, *model, options);
  if (!plan) return fail(plan.error());

  const music::Score fingered = fingered_score(*score, plan->fingering);
  if (Status s = write_output(*format, o, fingered, *plan, out); !s) return fail(s.error());
  if (!o.plot.empty()) {
    const PlotImage image = plot_piano_roll(fingered, *plan, model->keyboard, window);
    if (Status s = write_png(o.plot, image); !s) return fail(s.error());
  }
  // The report goes where it does not mix with data: stdout when the data went to a file.
  const bool data_on_stdout = o.output.empty();
  (data_on_stdout ? err : out) << fingering_report_text(*score, *plan);
  return kExitOk;
}

void register_fingering_command(Commands& commands) {
  auto options = std::make_shared<FingeringOptions>();
  Command& command = commands.add(
      "fingering",
      "Plan piano fingering and hand paths for a MIDI, MusicXML or PIG file; write MusicXML "
      "(marks added to the input), PIG, MIDI (lyric events \"RH3:64\") or JSON");
  command.option("IN", options->input, "score file").required();
  command.option("-o,--output", options->output,
                 "output file (format from .musicxml/.xml, .txt/.pig, .mid, .json); "
                 "none = a listing on stdout");
  command.option("--format", options->format, "musicxml, pig, midi or json");
  command.option("--mode", options->mode, "exact (default) or lookahead");
  command.option("--lookahead", options->lookahead, "events, for --mode lookahead");
  command.option("--hand-size", options->hand_size, "small, medium or large");
  command.option("--weights", options->weights, "cost weights: default, paper, or a .json file");
  command.flag("--keep-fingers", options->keep_fingers,
               "keep the file's finger marks as pins (else they are ignored)");
  command.option("--smoothing", options->smoothing,
                 "hand-path smoothing: monotone_quintic (default), pchip, "
                 "natural_spline or none");
  command.option("--plot", options->plot, "write a piano-roll PNG");
  command.option("--plot-seconds", options->plot_seconds, "plot window A:B seconds");
  command.on_run([options](std::ostream& out, std::ostream& err) {
    return run_fingering(*options, out, err);
  });
}

}  // namespace tutti::cli
