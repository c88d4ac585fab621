// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/exact_planner.hpp>

#include <vector>

#include <tutti/fingering_planner/event_dp.hpp>
#include <tutti/fingering_planner/hand_events.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::HandCorridor;

Result<HandPlan> plan_hand_exact(std::span<const PlanNote> notes, music::Hand side,
                                 const FingeringModel& model,
                                 std::span<const HandCorridor> other_hand) {
  auto prepared = prepare_hand(notes, side, model, other_hand);
  if (!prepared) return prepared.error();
  const PreparedHand& hand = *prepared;
  if (hand.events.empty()) {
    HandPlan empty;
    empty.hand = side;
    return empty;
  }
  std::vector<int> chosen(hand.events.size(), -1);
  std::vector<Diagnostic> extra;
  solve_event_range(hand, model, {0, static_cast<int>(hand.events.size()) - 1, -1, -1}, chosen,
                    extra);
  HandPlan plan = finish_plan(hand, chosen, notes, model);
  for (Diagnostic& d : extra) plan.diagnostics.push_back(std::move(d));
  return plan;
}

}  // namespace tutti::fingering_planner
