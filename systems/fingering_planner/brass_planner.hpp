// SPDX-License-Identifier: MIT
#pragma once
// Which valves / slide position play every note of a brass player's line: the cheapest fingering
// for the whole line at once (dynamic programming over the notes, a state per fingering of the
// note; linear in the line's length), like the piano's exact planner.
//
// Cost (weights in content/brass/planner.json):
//   per note:       alternate_rank × rank (0 = the standard fingering) + tuning_per_cent × |cents|
//   between notes:  rate = min(rate_cap, rate_reference_s / time between the onsets): moves
//                   cost more the faster the notes come, so alternates pay off in trills and
//                   fast passages, not elsewhere;
//                   valves: valve_change × (valves that move) × rate;
//                   slide: (slide_per_100mm × travel + slide_rush × (needed / available)²) × rate,
//                   infeasible when the slide cannot get there at its maximum speed (minimum-jerk
//                   move, peak speed 1.875 × distance / duration) in the time available: the
//                   rest between the notes plus the end of the previous note (release_fraction of
//                   it, at most release_max_s).
// Notes outside the range are reported (part, bar, time, pitch) and left unplayed. Moves no
// fingering can make in time are reported and the least-bad one is used.

#include <string>
#include <vector>

#include <tutti/brass_model/brass_line.hpp>
#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>

namespace tutti::fingering_planner {

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::ChangeWindow;

struct PlannerWeights {
  double alternate_rank = 1.0;
  double tuning_per_cent = 0.02;
  double valve_change = 0.25;
  double rate_reference_s = 0.25;
  double rate_cap = 6.0;
  double slide_per_100mm = 1.0;
  double slide_rush = 1.0;
  double beyond_reach = 20.0;  // a slide position past the instrument's slide_reach_mm
  ChangeWindow change;  // release_fraction, release_max_s
  double impossible = 1e6;
};

// content/brass/planner.json, or another file of the same form. Errors name file and JSON path.
Result<PlannerWeights> load_planner_weights();
Result<PlannerWeights> load_planner_weights(const std::string& file);

enum class BrassIssue { out_of_range, slide_too_slow, beyond_reach };

struct BrassDiagnostic {
  BrassIssue kind = BrassIssue::out_of_range;
  int note = -1;  // index into BrassLine::notes
  double time_s = 0.0;
  int bar = 0;
  std::string message;  // one line: "<file>: Trumpet 1, bar 12 (24.50 s): C7 (written D7) ..."
};

struct BrassPlanSummary {
  int notes = 0;
  int unplayable = 0;  // out of range
  int alternates = 0;
  int infeasible_moves = 0;
  double slide_travel_mm = 0.0;
  double total_cost = 0.0;
  std::vector<BrassDiagnostic> diagnostics;
};

// Chooses LineNote::fingering / alternate for every playable note of `line` (in place); the line
// must have its instrument. `score` (optional) names the file and gives bar numbers in messages.
BrassPlanSummary plan_line(BrassLine& line, const PlannerWeights& w,
                           const music::Score* score = nullptr);

}  // namespace tutti::fingering_planner
