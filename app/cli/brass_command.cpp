// SPDX-License-Identifier: MIT
#include <tutti/cli/brass_command.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include <tutti/core/exit_codes.hpp>
#include <tutti/brass_model/instrument.hpp>
#include <tutti/brass_motion/brass_motion_params.hpp>
#include <tutti/brass_motion/breath_params.hpp>
#include <tutti/brass_motion/breath_plan.hpp>
#include <tutti/brass_motion/plan_brass_motion.hpp>
#include <tutti/brass_motion/plan_brass_player.hpp>
#include <tutti/fingering_planner/brass_lines.hpp>
#include <tutti/fingering_planner/brass_planner.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/music/pitch.hpp>

namespace tutti::cli {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// The part `wanted` names: a 1-based index, else a name (exact, then contained), -1 = none.
int find_part(const music::Score& score, const std::string& wanted) {
  if (!wanted.empty() && std::all_of(wanted.begin(), wanted.end(),
                                     [](unsigned char c) { return std::isdigit(c) != 0; })) {
    const long index = std::strtol(wanted.c_str(), nullptr, 10);
    return index >= 1 && static_cast<std::size_t>(index) <= score.parts.size()
               ? static_cast<int>(index - 1)
               : -1;
  }
  const std::string key = lower(wanted);
  for (std::size_t p = 0; p < score.parts.size(); ++p) {
    if (lower(score.parts[p].name) == key) return static_cast<int>(p);
  }
  for (std::size_t p = 0; p < score.parts.size(); ++p) {
    if (lower(score.parts[p].name).find(key) != std::string::npos) return static_cast<int>(p);
  }
  return -1;
}

std::string part_list(const music::Score& score) {
  std::string text;
  for (std::size_t p = 0; p < score.parts.size(); ++p) {
    if (!text.empty()) text += ", ";
    text += std::to_string(p + 1) + " \"" + score.parts[p].name + "\"";
  }
  return text.empty() ? "none" : text;
}

std::string instrument_list(const std::vector<brass_model::Instrument>& known) {
  std::string text;
  for (const brass_model::Instrument& i : known) text += (text.empty() ? "" : ", ") + i.id;
  return text;
}

const char* breath_kind_name(brass_motion::BreathKind kind) {
  switch (kind) {
    case brass_motion::BreathKind::before_entrance:
      return "before_entrance";
    case brass_motion::BreathKind::in_rest:
      return "in_rest";
    case brass_motion::BreathKind::last_beat:
      return "last_beat";
    case brass_motion::BreathKind::prepared:
      return "prepared";
    case brass_motion::BreathKind::catch_breath:
      return "catch_breath";
  }
  return "?";
}

struct PlayerReport {
  brass_model::BrassLine line;
  fingering_planner::BrassPlanSummary summary;
  brass_motion::BreathPlan breaths;
};

nlohmann::json player_json(const PlayerReport& r, const brass_motion::BrassMotionParams& motion) {
  const brass_model::Instrument& instrument = *r.line.instrument;
  nlohmann::json notes = nlohmann::json::array();
  for (const brass_model::LineNote& n : r.line.notes) {
    nlohmann::json note = {{"onset_s", n.onset_s},
                           {"offset_s", n.offset_s},
                           {"score_note", n.score_index},
                           {"sounding", music::pitch_name(n.sounding)},
                           {"written", music::pitch_name(n.written)},
                           {"playable", n.playable}};
    if (n.fingering >= 0) {
      const brass_model::Fingering& f = instrument.chart[static_cast<std::size_t>(n.fingering)];
      note["fingering"] = brass_model::fingering_name(instrument, f);
      note["partial"] = f.partial;
      if (instrument.mechanism == brass_model::Mechanism::slide) {
        note["position"] = f.position;
        note["slide_mm"] = f.slide_mm;
      }
      note["alternate"] = n.alternate;
      note["tension"] = brass_motion::embouchure_tension(instrument, n.written, motion);
    }
    notes.push_back(std::move(note));
  }
  nlohmann::json breaths = nlohmann::json::array();
  for (const brass_motion::BreathEvent& b : r.breaths.events) {
    breaths.push_back({{"kind", breath_kind_name(b.kind)},
                       {"prepare_start_s", b.prepare_start_s},
                       {"start_s", b.start_s},
                       {"end_s", b.end_s},
                       {"depth", b.depth},
                       {"before_note", b.before_note}});
  }
  nlohmann::json diagnostics = nlohmann::json::array();
  for (const fingering_planner::BrassDiagnostic& d : r.summary.diagnostics)
    diagnostics.push_back(d.message);
  return {{"part", r.line.part + 1},
          {"name", r.line.part_name},
          {"voice", r.line.voice + 1},
          {"instrument", instrument.id},
          {"notes", std::move(notes)},
          {"breaths", std::move(breaths)},
          {"unplayable", r.summary.unplayable},
          {"alternates", r.summary.alternates},
          {"slide_travel_mm", r.summary.slide_travel_mm},
          {"infeasible_moves", r.summary.infeasible_moves},
          {"diagnostics", std::move(diagnostics)}};
}

void player_text(const PlayerReport& r, const brass_motion::BrassMotionParams& motion,
                 std::ostream& out) {
  const brass_model::Instrument& instrument = *r.line.instrument;
  out << "part " << r.line.part + 1 << " \"" << r.line.part_name << "\" voice " << r.line.voice + 1
      << ": " << instrument.display_name << " (" << instrument.id << "), " << r.line.notes.size()
      << " notes, " << r.summary.alternates << " alternates, " << r.summary.unplayable
      << " out of range, " << r.breaths.events.size() << " breaths";
  if (instrument.mechanism == brass_model::Mechanism::slide) {
    char travel[64];
    std::snprintf(travel, sizeof travel, ", slide travel %.0f mm", r.summary.slide_travel_mm);
    out << travel;
  }
  out << "\n";
  std::size_t next_breath = 0;
  for (const brass_model::LineNote& n : r.line.notes) {
    while (next_breath < r.breaths.events.size() &&
           r.breaths.events[next_breath].start_s <= n.onset_s) {
      const brass_motion::BreathEvent& b = r.breaths.events[next_breath++];
      char line[128];
      std::snprintf(line, sizeof line, "  %9.3f  breath (%s) until %.3f s, depth %.2f\n", b.start_s,
                    breath_kind_name(b.kind), b.end_s, b.depth);
      out << line;
    }
    char line[160];
    if (n.fingering < 0) {
      std::snprintf(line, sizeof line, "  %9.3f  %-4s (written %-4s)  out of range, not played\n",
                    n.onset_s, music::pitch_name(n.sounding).c_str(),
                    music::pitch_name(n.written).c_str());
    } else {
      const brass_model::Fingering& f = instrument.chart[static_cast<std::size_t>(n.fingering)];
      std::snprintf(line, sizeof line,
                    "  %9.3f  %-4s (written %-4s)  %-7s partial %2d  tension %.2f%s\n", n.onset_s,
                    music::pitch_name(n.sounding).c_str(), music::pitch_name(n.written).c_str(),
                    brass_model::fingering_name(instrument, f).c_str(), f.partial,
                    brass_motion::embouchure_tension(instrument, n.written, motion),
                    n.alternate ? "  (alternate)" : "");
    }
    out << line;
  }
  for (const fingering_planner::BrassDiagnostic& d : r.summary.diagnostics)
    out << "  note: " << d.message << "\n";
}

}  // namespace

int run_brass(const BrassOptions& options, std::ostream& out, std::ostream& err) {
  const Fail fail{err};
  auto score = music::load_score(options.file);
  if (!score) return fail(score.error());
  auto known = brass_model::load_all_instruments();
  if (!known) return fail(known.error());
  auto weights = fingering_planner::load_planner_weights();
  if (!weights) return fail(weights.error());
  auto motion = brass_motion::load_brass_motion_params();
  if (!motion) return fail(motion.error());
  auto breath_params = brass_motion::load_breath_params();
  if (!breath_params) return fail(breath_params.error());

  const brass_model::Instrument* forced = nullptr;
  if (!options.instrument.empty()) {
    for (const brass_model::Instrument& i : *known)
      forced = i.id == options.instrument ? &i : forced;
    if (forced == nullptr) {
      return fail("no instrument \"" + options.instrument +
                  "\" (known: " + instrument_list(*known) + ")");
    }
  }
  std::vector<fingering_planner::BrassPart> parts;
  if (!options.part.empty()) {
    const int part = find_part(*score, options.part);
    if (part < 0) {
      return fail(options.file.string() + ": no part \"" + options.part +
                  "\" (parts: " + part_list(*score) + ")");
    }
    const brass_model::Instrument* instrument =
        forced != nullptr
            ? forced
            : brass_model::detect_instrument(score->parts[static_cast<std::size_t>(part)], *known);
    if (instrument == nullptr) {
      return fail(options.file.string() + ": part " + std::to_string(part + 1) + " \"" +
                  score->parts[static_cast<std::size_t>(part)].name +
                  "\" is not a brass instrument tutti knows; name one with --instrument (" +
                  instrument_list(*known) + ")");
    }
    parts.push_back({part, instrument, fingering_planner::voices_in_part(*score, part)});
  } else {
    parts = fingering_planner::find_brass_parts(*score, *known);
    if (forced != nullptr) {
      for (fingering_planner::BrassPart& p : parts) p.instrument = forced;
    }
    if (parts.empty()) {
      return fail(options.file.string() + ": no brass parts found (parts: " + part_list(*score) +
                  "); choose one with --part and --instrument");
    }
  }

  std::vector<PlayerReport> players;
  for (const fingering_planner::BrassPart& part : parts) {
    if (options.voice > part.voices) {
      return fail(options.file.string() + ": part " + std::to_string(part.part + 1) + " has " +
                  std::to_string(part.voices) + " voice(s), not " + std::to_string(options.voice));
    }
    for (int voice = 0; voice < part.voices; ++voice) {
      if (options.voice > 0 && voice != options.voice - 1) continue;
      auto line = fingering_planner::extract_line(*score, part.part, voice, *part.instrument);
      if (!line) return fail(line.error());
      PlayerReport report;
      report.line = std::move(*line);
      report.summary =
          brass_motion::plan_line_around_breaths(report.line, *score, *weights, *breath_params);
      report.breaths = brass_motion::plan_breaths(report.line, *score, *breath_params);
      players.push_back(std::move(report));
    }
  }
  if (options.json) {
    nlohmann::json players_json = nlohmann::json::array();
    for (const PlayerReport& r : players) players_json.push_back(player_json(r, *motion));
    out << nlohmann::json{{"file", options.file.string()}, {"players", std::move(players_json)}}
               .dump(2)
        << "\n";
  } else {
    for (const PlayerReport& r : players) player_text(r, *motion, out);
  }
  return kExitOk;
}

void register_brass_command(Commands& commands) {
  auto options = std::make_shared<BrassOptions>();
  Command& command = commands.add(
      "brass",
      "How every brass player of a score plays: valves or slide position per note (alternates "
      "marked), mouth tension, breaths, notes out of range");
  command.option("FILE", options->file, "score file").required();
  command.option("--part", options->part, "part name (or part of it) or 1-based index");
  command.option("--voice", options->voice, "1-based player within the part (default: all)");
  command.option("--instrument", options->instrument,
                 "instrument id from content/instruments (default: detected)");
  command.flag("--json", options->json, "print JSON instead of text");
  command.on_run(
      [options](std::ostream& out, std::ostream& err) { return run_brass(*options, out, err); });
}

}  // namespace tutti::cli
