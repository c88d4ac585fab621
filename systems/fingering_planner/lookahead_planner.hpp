// SPDX-License-Identifier: MIT
#pragma once
// The paper's search (Sekiguchi & Eiho 1999): fingering is decided event by event; at each event
// every fingering sequence of the next `lookahead` events (this one included) is evaluated from
// the already chosen previous fingering, and only the first step of the cheapest is kept. Cheaper
// and streamable, but not globally optimal; kept for comparison with the exact planner. Same
// cost model, inputs, outputs and fallbacks as plan_hand_exact.

#include <span>

#include <tutti/core/result.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/fingering_planner/hand_plan.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::HandCorridor;

// `lookahead` >= 1 (1 = pure greedy). Errors: invalid notes, lookahead < 1.
Result<HandPlan> plan_hand_lookahead(std::span<const PlanNote> notes, music::Hand side,
                                     const FingeringModel& model, int lookahead,
                                     std::span<const HandCorridor> other_hand = {});

}  // namespace tutti::fingering_planner
