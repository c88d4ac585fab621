// SPDX-License-Identifier: MIT
#pragma once
// Fingering for a whole Score: hands assigned (hand_assignment.hpp), each hand planned
// (exact DP by default, or the paper's lookahead search), results mapped back to Score::notes.
// With the weights' other_hand term (other_hand_cost.hpp) the hands are planned beside each
// other: the right hand alone, the left beside it, then the right beside the left and the left
// beside that right hand, so each hand's plan is priced against the other's final corridors.
// A local re-plan keeps that: each hand beside the other's current plan, and the left hand
// searched again where the right hand changed.
//
// Pins: with `pins_from_marks`, every Note::finger 1..5 in the file is a hard constraint
// (the editor will pin the same way). Strip Note::finger first to plan from scratch.
// Keys outside the keyboard are clamped to its ends for planning (reported as a diagnostic).
// Diagnostics carry Score::notes indices and 1-based bar numbers.

#include <span>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/fingering_planner/hand_assignment.hpp>
#include <tutti/fingering_planner/hand_plan.hpp>
#include <tutti/music/score.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::HandCorridor;

enum class PlannerMode { exact, lookahead };

struct PlanOptions {
  PlannerMode mode = PlannerMode::exact;
  int lookahead = 4;            // events, for PlannerMode::lookahead
  bool pins_from_marks = true;  // Note::finger in the file = pinned
  // Give the planner each note's tonic (PlanNote::tonic; used by fingers.thumb_on_tonic): from the
  // key signature in force, else the major / harmonic-minor key that the notes fit best.
  bool tonic_from_key = true;
};

struct ScorePlan {
  HandPlan right;  // diagnostics' notes are Score::notes indices
  HandPlan left;
  std::vector<int> right_notes;  // Score::notes index of each right-hand input note
  std::vector<int> left_notes;
  std::vector<int> fingers;        // per Score::notes entry, 1..5, 0 = not planned (percussion)
  std::vector<music::Hand> hands;  // per Score::notes entry
};

Result<ScorePlan> plan_score(const music::Score& score, const FingeringModel& model,
                             const PlanOptions& options = {});

// After the pins of the notes `edited` (Score::notes indices; e.g. a finger pinned in the
// editor: Note::finger set, options.pins_from_marks) changed, re-plans only the affected span of
// each hand (local_replan.hpp); every other note keeps the finger it has in `previous`, and the
// hand assignment is kept. `score` is the one `previous` was planned from, apart from the pins.
struct ScoreReplanSpan {
  int changed_notes = 0;    // notes whose finger changed
  int searched_events = 0;  // events searched again (both hands)
  int event_count = 0;      // events of the hands that were re-planned
  double first_changed_s = 0.0;
  double last_changed_s = 0.0;
};
Result<ScorePlan> replan_score_locally(const music::Score& score, const FingeringModel& model,
                                       const PlanOptions& options, const ScorePlan& previous,
                                       std::span<const int> edited,
                                       ScoreReplanSpan* span = nullptr);

// Plans one hand with the chosen mode.
Result<HandPlan> plan_hand(std::span<const PlanNote> notes, music::Hand side,
                           const FingeringModel& model, const PlanOptions& options = {},
                           std::span<const HandCorridor> other_hand = {});

// Tonic pitch class (0 = C .. 11) per Score::notes entry: the key signature in force at the note
// (fifths, minor flag); without key signatures, the major or harmonic-minor scale containing most
// notes (duration-weighted; ties: major first, then the tonic of the lowest first note).
std::vector<int> note_tonics(const music::Score& score);

}  // namespace tutti::fingering_planner
