// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/brass_planner.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>

#include <tutti/content/content_dir.hpp>
#include <tutti/content/json_reader.hpp>
#include <tutti/music/meter.hpp>
#include <tutti/music/pitch.hpp>

namespace tutti::fingering_planner {

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::change_window_s;
using brass_model::Fingering;
using brass_model::Instrument;
using brass_model::LineNote;

namespace {

constexpr double kUnset = std::numeric_limits<double>::infinity();

bool beyond_reach(const Fingering& f, const Instrument& instrument) {
  return instrument.slide_reach_mm > 0.0 && double(f.slide_mm) > instrument.slide_reach_mm;
}

double strike_cost(const Fingering& f, const Instrument& instrument, const PlannerWeights& w) {
  return w.alternate_rank * f.rank + w.tuning_per_cent * std::abs(f.cents) +
         (beyond_reach(f, instrument) ? w.beyond_reach : 0.0);
}

struct Move {
  double cost = 0.0;
  bool feasible = true;
};

Move move_cost(const Fingering& a, const Fingering& b, double window_s, double ioi_s,
               const Instrument& instrument, const PlannerWeights& w) {
  Move m;
  // Changes cost more the faster the notes come (a trill, a run), up to a cap.
  const double rate = std::min(w.rate_cap, w.rate_reference_s / std::max(ioi_s, 1e-3));
  const int changed = std::popcount(static_cast<unsigned>(a.valves ^ b.valves));
  m.cost += w.valve_change * changed * rate;
  const double distance = std::abs(double(a.slide_mm) - double(b.slide_mm));
  if (distance > 0.0) {
    const double needed = 1.875 * distance / instrument.max_slide_speed_mm_per_s;
    m.feasible = needed <= window_s + 1e-9;
    const double ratio = window_s > 0.0 ? needed / window_s : 1e9;
    m.cost += (w.slide_per_100mm * distance / 100.0 + w.slide_rush * ratio * ratio) * rate;
    if (!m.feasible) m.cost += w.impossible;
  }
  return m;
}

std::string at_text(const music::Score* score, const BrassLine& line, const LineNote& note,
                    int* bar) {
  *bar = score != nullptr ? music::bar_at_beats(*score, note.onset_beats)
                          : 1 + static_cast<int>(std::floor(note.onset_beats / 4.0 + 1e-9));
  char time[32];
  std::snprintf(time, sizeof time, "%.2f s", note.onset_s);
  std::string who =
      line.part_name.empty() ? "part " + std::to_string(line.part + 1) : line.part_name;
  if (line.voice > 0) who += " (voice " + std::to_string(line.voice + 1) + ")";
  std::string prefix = score != nullptr && !score->source.empty() ? score->source + ": " : "";
  return prefix + who + ", bar " + std::to_string(*bar) + " (" + time + ")";
}

}  // namespace

Result<PlannerWeights> load_planner_weights() {
  return load_planner_weights((content::default_content_dir() / "brass" / "planner.json").string());
}

Result<PlannerWeights> load_planner_weights(const std::string& file) {
  auto document = content::read_json_file(file);
  if (!document) return document.error();
  const content::JsonReader reader(file);
  PlannerWeights w;
  const double any = 1e12;
  const content::NumberField fields[] = {{"alternate_rank", &w.alternate_rank, 0.0, any},
                                         {"tuning_per_cent", &w.tuning_per_cent, 0.0, any},
                                         {"valve_change", &w.valve_change, 0.0, any},
                                         {"rate_reference_s", &w.rate_reference_s, 1e-3, 10.0},
                                         {"rate_cap", &w.rate_cap, 0.0, any},
                                         {"slide_per_100mm", &w.slide_per_100mm, 0.0, any},
                                         {"slide_rush", &w.slide_rush, 0.0, any},
                                         {"beyond_reach", &w.beyond_reach, 0.0, any},
                                         {"release_fraction", &w.change.release_fraction, 0.0, 1.0},
                                         {"release_max_s", &w.change.release_max_s, 0.0, 10.0},
                                         {"impossible", &w.impossible, 1.0, any}};
  if (auto ok = reader.read_number_fields(*document, "", fields, /*required=*/false); !ok) {
    return ok.error();
  }
  return w;
}

BrassPlanSummary plan_line(BrassLine& line, const PlannerWeights& w, const music::Score* score) {
  BrassPlanSummary summary;
  summary.notes = static_cast<int>(line.notes.size());
  if (line.instrument == nullptr) return summary;
  const Instrument& instrument = *line.instrument;

  // Playable notes with their fingerings, as ranges of the chart.
  std::vector<int> playable;
  playable.reserve(line.notes.size());
  for (std::size_t i = 0; i < line.notes.size(); ++i) {
    LineNote& note = line.notes[i];
    note.fingering = -1;
    note.alternate = false;
    note.playable =
        instrument.in_range_written(note.written) && !instrument.fingerings(note.written).empty();
    if (note.playable) {
      playable.push_back(static_cast<int>(i));
      continue;
    }
    ++summary.unplayable;
    BrassDiagnostic d;
    d.kind = BrassIssue::out_of_range;
    d.note = static_cast<int>(i);
    d.time_s = note.onset_s;
    d.message = at_text(score, line, note, &d.bar) + ": " + music::pitch_name(note.sounding) +
                " (written " + music::pitch_name(note.written) + ") is outside the " +
                instrument.display_name + "'s range " +
                music::pitch_name(instrument.lowest_written) + ".." +
                music::pitch_name(instrument.highest_written) + " (written); left unplayed";
    summary.diagnostics.push_back(std::move(d));
  }
  if (playable.empty()) return summary;

  auto options = [&](int note) {
    return instrument.fingerings(line.notes[static_cast<std::size_t>(note)].written);
  };
  auto chart_index = [&](const Fingering& f) {
    return static_cast<int>(&f - instrument.chart.data());
  };
  // best / back per (playable note, option), flattened.
  std::vector<int> begin(playable.size() + 1, 0);
  for (std::size_t k = 0; k < playable.size(); ++k) {
    begin[k + 1] = begin[k] + static_cast<int>(options(playable[k]).size());
  }
  std::vector<double> best(static_cast<std::size_t>(begin.back()), kUnset);
  std::vector<int> back(static_cast<std::size_t>(begin.back()), -1);
  {
    const auto first = options(playable[0]);
    for (std::size_t o = 0; o < first.size(); ++o) best[o] = strike_cost(first[o], instrument, w);
  }
  for (std::size_t k = 1; k < playable.size(); ++k) {
    const LineNote& from = line.notes[static_cast<std::size_t>(playable[k - 1])];
    const LineNote& to = line.notes[static_cast<std::size_t>(playable[k])];
    const double window = change_window_s(from, to, w.change);
    const double ioi = to.onset_s - from.onset_s;
    const auto before = options(playable[k - 1]);
    const auto now = options(playable[k]);
    for (std::size_t b = 0; b < now.size(); ++b) {
      double best_cost = kUnset;
      int best_prev = -1;
      for (std::size_t a = 0; a < before.size(); ++a) {
        const double base = best[static_cast<std::size_t>(begin[k - 1]) + a];
        const double total = base + move_cost(before[a], now[b], window, ioi, instrument, w).cost;
        if (total < best_cost) best_cost = total, best_prev = static_cast<int>(a);
      }
      best[static_cast<std::size_t>(begin[k]) + b] = best_cost + strike_cost(now[b], instrument, w);
      back[static_cast<std::size_t>(begin[k]) + b] = best_prev;
    }
  }
  // Back-track; ties go to the lowest option (the standard fingering first).
  std::vector<int> chosen(playable.size(), 0);
  {
    const std::size_t last = playable.size() - 1;
    double best_total = kUnset;
    for (int o = 0; o < begin[last + 1] - begin[last]; ++o) {
      const double total = best[static_cast<std::size_t>(begin[last] + o)];
      if (total < best_total) best_total = total, chosen[last] = o;
    }
    for (std::size_t k = last; k > 0; --k) {
      chosen[k - 1] = back[static_cast<std::size_t>(begin[k] + chosen[k])];
    }
  }

  const Fingering* previous = nullptr;
  for (std::size_t k = 0; k < playable.size(); ++k) {
    LineNote& note = line.notes[static_cast<std::size_t>(playable[k])];
    const Fingering& f = options(playable[k])[static_cast<std::size_t>(chosen[k])];
    note.fingering = chart_index(f);
    note.alternate = f.rank > 0;
    summary.alternates += note.alternate;
    summary.total_cost += strike_cost(f, instrument, w);
    if (beyond_reach(f, instrument)) {
      // No other position for this note: the player leans for it (the pose turns the chest).
      BrassDiagnostic d;
      d.kind = BrassIssue::beyond_reach;
      d.note = playable[k];
      d.time_s = note.onset_s;
      char what[160];
      std::snprintf(what, sizeof what,
                    ": %s needs position %d, %.0f mm out, beyond the arm's reach (%.0f mm); "
                    "the player leans for it",
                    music::pitch_name(note.sounding).c_str(), int(f.position), double(f.slide_mm),
                    instrument.slide_reach_mm);
      d.message = at_text(score, line, note, &d.bar) + what;
      summary.diagnostics.push_back(std::move(d));
    }
    if (previous != nullptr) {
      const LineNote& from = line.notes[static_cast<std::size_t>(playable[k - 1])];
      const Move m = move_cost(*previous, f, change_window_s(from, note, w.change),
                               note.onset_s - from.onset_s, instrument, w);
      summary.slide_travel_mm += std::abs(double(previous->slide_mm) - double(f.slide_mm));
      if (m.feasible) {
        summary.total_cost += m.cost;
      } else {
        ++summary.infeasible_moves;
        BrassDiagnostic d;
        d.kind = BrassIssue::slide_too_slow;
        d.note = playable[k];
        d.time_s = note.onset_s;
        char what[160];
        std::snprintf(what, sizeof what,
                      ": the slide cannot move %.0f mm from %s to %s in %.0f ms at its top speed; "
                      "it arrives late",
                      std::abs(double(previous->slide_mm) - double(f.slide_mm)),
                      music::pitch_name(from.sounding).c_str(),
                      music::pitch_name(note.sounding).c_str(),
                      1000.0 * change_window_s(from, note, w.change));
        d.message = at_text(score, line, note, &d.bar) + what;
        summary.diagnostics.push_back(std::move(d));
      }
    }
    previous = &f;
  }
  std::stable_sort(
      summary.diagnostics.begin(), summary.diagnostics.end(),
      [](const BrassDiagnostic& a, const BrassDiagnostic& b) { return a.time_s < b.time_s; });
  return summary;
}

}  // namespace tutti::fingering_planner
