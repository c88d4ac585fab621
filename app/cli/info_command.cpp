// SPDX-License-Identifier: MIT
#include <tutti/cli/info_command.hpp>

#include <memory>
#include <ostream>
#include <string>
#include <utility>

#include <tutti/core/exit_codes.hpp>
#include <tutti/cli/score_summary.hpp>
#include <tutti/core/file_io.hpp>
#include <tutti/components/breath.hpp>
#include <tutti/components/finger.hpp>
#include <tutti/components/hand.hpp>
#include <tutti/components/instrument.hpp>
#include <tutti/components/mouth.hpp>
#include <tutti/components/note.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/valve.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/scene/load_scene.hpp>

namespace tutti::cli {

namespace {

int run_schedule_info(const InfoOptions& options, std::ostream& out, std::ostream& err) {
  auto scene = scene::load_scene(options.file, performance::scene_load_options());
  if (!scene) {
    err << "error: " << scene.error().message << "\n";
    return kExitBadInput;
  }
  auto stage = performance::build_stage(*scene);
  if (!stage) {
    err << "error: " << scene->source << ": " << stage.error().message << "\n";
    return kExitBadInput;
  }
  const ecs::World& world = (*stage)->world();
  // A stage is built only when its schedule's check() finds nothing, so every two writers of one
  // component in a phase are ordered (or each writes only its own family's entities).
  out << "schedule of " << scene->source
      << " (phases in run order, systems in order; checked: writers of one component in a phase "
         "are ordered, or each writes its own family's entities):\n"
      << (*stage)->schedule().describe_access();
  const std::pair<const char*, std::size_t> counts[] = {
      {"Performer", world.size<components::Performer>()},
      {"Note", world.size<components::Note>()},
      {"Hand", world.size<components::Hand>()},
      {"Finger", world.size<components::Finger>()},
      {"Instrument", world.size<components::Instrument>()},
      {"Valve", world.size<components::Valve>()},
      {"Slide", world.size<components::Slide>()},
      {"Mouth", world.size<components::Mouth>()},
      {"Breath", world.size<components::Breath>()},
      {"PlacedModel", (*stage)->instances().size()}};
  out << "entities:";
  for (const auto& [name, count] : counts) out << " " << count << " " << name << ",";
  out << " " << world.alive() << " in all\n";
  return kExitOk;
}

}  // namespace

int run_info(const InfoOptions& options, std::ostream& out, std::ostream& err) {
  if (options.schedule) return run_schedule_info(options, out, err);
  auto score = music::load_score(options.file);
  if (!score) {
    err << "error: " << score.error().message << "\n";
    return kExitBadInput;
  }
  // load_score already succeeded, so the bytes are readable; detect again only for the label.
  auto bytes = read_file_bytes(options.file);
  const auto format = bytes ? music::detect_score_format(*bytes, options.file)
                            : std::optional<music::ScoreFormat>{};
  const ScoreSummary summary = summarize(*score, format ? music::format_name(*format) : "unknown");
  out << (options.json ? summary_json(summary) : summary_text(summary));
  return kExitOk;
}

void register_info_command(Commands& commands) {
  auto options = std::make_shared<InfoOptions>();
  Command& command = commands.add("info",
                                  "Parts, notes, duration, tempo and ranges of a "
                                  "MIDI, MusicXML (.xml/.musicxml/.mxl) or PIG file");
  command.option("FILE", options->file, "score file").required();
  command.flag("--json", options->json, "print JSON instead of text");
  command.flag("--schedule", options->schedule,
               "FILE is a scene: print the frame (phases, systems, components)");
  command.on_run(
      [options](std::ostream& out, std::ostream& err) { return run_info(*options, out, err); });
}

}  // namespace tutti::cli
