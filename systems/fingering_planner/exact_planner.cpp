#include "fingering_planner/exact_planner.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "fingering_planner/hand_events.hpp"

namespace tutti::piano {

Result<HandPlan> plan_hand_exact(std::span<const PlanNote> notes, music::Hand side,
                                 const FingeringModel& model) {
  auto prepared = prepare_hand(notes, side, model);
  if (!prepared) return prepared.error();
  const PreparedHand& hand = *prepared;
  if (hand.events.empty()) {
    HandPlan empty;
    empty.hand = side;
    return empty;
  }
  const double impossible = model.weights.impossible;
  constexpr double kUnset = std::numeric_limits<double>::infinity();
  std::vector<double> best(hand.candidates.size(), kUnset);
  std::vector<int> back(hand.candidates.size(), -1);
  std::vector<Diagnostic> extra;

  const HandEvent& first = hand.events.front();
  for (int c = first.cand_begin; c < first.cand_end; ++c) {
    best[static_cast<std::size_t>(c)] = hand.candidates[static_cast<std::size_t>(c)].strike;
  }
  for (std::size_t e = 1; e < hand.events.size(); ++e) {
    const HandEvent& prev = hand.events[e - 1];
    const HandEvent& event = hand.events[e];
    bool any = false;
    for (int pass = 0; pass < 2 && !any; ++pass) {
      const bool check_held = pass == 0;  // second pass: held fingers could not be kept
      for (int b = event.cand_begin; b < event.cand_end; ++b) {
        const Candidate& cb = hand.candidates[static_cast<std::size_t>(b)];
        double best_cost = kUnset;
        int best_prev = -1;
        for (int a = prev.cand_begin; a < prev.cand_end; ++a) {
          const Candidate& ca = hand.candidates[static_cast<std::size_t>(a)];
          const double base = best[static_cast<std::size_t>(a)];
          if (base == kUnset || (check_held && !held_compatible(ca, cb))) continue;
          double t = transition_cost(ca.shape, cb.shape, event.dt_s, side, model);
          if (std::isinf(t)) t = impossible;
          const double total = base + t;
          if (total < best_cost) best_cost = total, best_prev = a;
        }
        if (best_prev >= 0) {
          best[static_cast<std::size_t>(b)] = best_cost + cb.strike;
          back[static_cast<std::size_t>(b)] = best_prev;
          any = true;
        }
      }
      if (!any && check_held) {
        Diagnostic d;
        d.kind = DiagnosticKind::held_released;
        d.time_s = event.onset_s;
        d.message = "at " + std::to_string(event.onset_s) +
                    " s: held keys cannot keep their fingers with these new keys; released";
        extra.push_back(std::move(d));
      }
    }
  }

  std::vector<int> chosen(hand.events.size(), -1);
  const HandEvent& last = hand.events.back();
  double best_total = kUnset;
  for (int c = last.cand_begin; c < last.cand_end; ++c) {
    if (best[static_cast<std::size_t>(c)] < best_total) {
      best_total = best[static_cast<std::size_t>(c)];
      chosen.back() = c;
    }
  }
  for (std::size_t e = hand.events.size() - 1; e > 0; --e) {
    chosen[e - 1] = back[static_cast<std::size_t>(chosen[e])];
  }
  HandPlan plan = finish_plan(hand, chosen, notes, model);
  for (Diagnostic& d : extra) plan.diagnostics.push_back(std::move(d));
  return plan;
}

}  // namespace tutti::piano
