// SPDX-License-Identifier: MIT
#pragma once
// The globally optimal fingering of one hand's notes: dynamic programming over events (notes
// starting together), the state being the fingers of every key sounding at the event (held keys
// included, so they keep their finger and keep constraining the hand). At most C(5,k) states per
// event, so time and memory are linear in the number of notes.
//
// Minimises Σ strike costs + Σ transition costs (transition_cost.hpp). Infinite transitions are
// avoided whenever possible; when unavoidable each counts `weights.impossible` in the search and
// is reported (HandPlan::impossible_transitions + a diagnostic). Pinned notes (PlanNote::pin) are
// hard constraints. Deterministic: ties go to the lowest candidate index.

#include <span>

#include <tutti/core/result.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/fingering_planner/hand_plan.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::HandCorridor;

// Errors: invalid input notes (see hand_plan.hpp). An empty input gives an empty plan.
// `other_hand`: the other hand's corridors, planned first (other_hand_cost.hpp); empty = alone.
Result<HandPlan> plan_hand_exact(std::span<const PlanNote> notes, music::Hand side,
                                 const FingeringModel& model,
                                 std::span<const HandCorridor> other_hand = {});

}  // namespace tutti::fingering_planner
