// SPDX-License-Identifier: MIT
#include <tutti/brass/plan_brass_player.hpp>

#include <cstdio>

#include <tutti/brass/brass_players.hpp>
#include <tutti/brass_motion/plan_brass_player.hpp>
#include <tutti/fingering_planner/brass_lines.hpp>
#include <tutti/scene/load_scene.hpp>

namespace tutti::brass {
namespace {

std::string times_key(const std::vector<double>& times) {
  std::string out;
  char text[32];
  for (double t : times) {
    std::snprintf(text, sizeof text, "%.17g,", t);
    out += text;
  }
  return out;
}

// Everything a brass player's own plan (line, fingering, breaths, valves / slide) depends on.
std::string brass_plan_key(const scene::Scene& scene, const BrassPlayer& performer) {
  return performer.instrument + "|" + performer.part + "|" + std::to_string(performer.voice) + "|" +
         scene.music[performer.music_file].string() + "|" + times_key(performer.breaths.add_s) +
         "|" + times_key(performer.breaths.remove_s);
}

}  // namespace

Result<BrassPlanningData> load_brass_planning_data(const std::filesystem::path& content_dir) {
  auto weights =
      fingering_planner::load_planner_weights((content_dir / "brass" / "planner.json").string());
  if (!weights) return weights.error();
  auto motion =
      brass_motion::load_brass_motion_params((content_dir / "brass" / "motion.json").string());
  if (!motion) return motion.error();
  auto breath = brass_motion::load_breath_params(content_dir / "brass" / "breath.json");
  if (!breath) return breath.error();
  return BrassPlanningData{std::move(*weights), std::move(*motion), std::move(*breath)};
}

Result<BrassPlan> plan_brass_seat(stage::StageBuilder& builder, std::size_t seat,
                                  const BrassPlanningData& data) {
  const scene::Scene& scene = builder.scene();
  const BrassPlayer& performer = brass_players(scene)[seat];
  const music::Score& score = builder.scores()[performer.music_file];
  BrassPlan plan;
  plan.plan_key = brass_plan_key(scene, performer);
  if (const stage::Stage* reuse = builder.previous(); reuse != nullptr) {
    const ecs::Entity previous_entity = reuse->find_performer("brass", seat);
    const auto* previous = previous_entity.is_null()
                               ? nullptr
                               : reuse->world().try_get<BrassPlan>(previous_entity);
    if (previous != nullptr && previous->plan_key == plan.plan_key && previous->line != nullptr) {
      return *previous;
    }
  }
  auto instrument = brass_model::load_instrument_by_id(performer.instrument, builder.content_dir());
  if (!instrument) return instrument.error();
  plan.instrument = std::make_shared<const brass_model::Instrument>(std::move(*instrument));
  const int part = scene::find_part(score, performer.part);
  if (part < 0) {
    return Error{scene.source + ": performer \"" + performer.name + "\": no part \"" +
                 performer.part + "\" in " +
                 scene.music[performer.music_file].filename().string()};
  }
  auto extracted =
      fingering_planner::extract_line(score, part, performer.voice - 1, *plan.instrument);
  if (!extracted) {
    return Error{scene.source + ": performer \"" + performer.name +
                 "\": " + extracted.error().message};
  }
  brass_motion::BreathMarks marks;
  marks.add_s = performer.breaths.add_s;
  marks.remove_s = performer.breaths.remove_s;
  const fingering_planner::BrassPlanSummary summary =
      brass_motion::plan_line_around_breaths(*extracted, score, data.weights, data.breath, marks);
  for (const fingering_planner::BrassDiagnostic& d : summary.diagnostics) {
    plan.plan_notes.push_back(performer.name + ": " + d.message);
  }
  plan.player =
      std::make_shared<const brass_motion::BrassPlayerMotion>(brass_motion::plan_brass_player(
          *extracted, score, data.motion, data.breath, data.weights.change, marks));
  plan.line = std::make_shared<const brass_model::BrassLine>(std::move(*extracted));
  builder.replanned(performer.name);
  return plan;
}

}  // namespace tutti::brass
