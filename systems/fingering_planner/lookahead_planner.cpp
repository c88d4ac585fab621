// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/lookahead_planner.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include <tutti/fingering_planner/hand_events.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::HandCorridor;

Result<HandPlan> plan_hand_lookahead(std::span<const PlanNote> notes, music::Hand side,
                                     const FingeringModel& model, int lookahead,
                                     std::span<const HandCorridor> other_hand) {
  if (lookahead < 1) return Error{"lookahead must be at least 1 event"};
  auto prepared = prepare_hand(notes, side, model, other_hand);
  if (!prepared) return prepared.error();
  const PreparedHand& hand = *prepared;
  HandPlan empty;
  empty.hand = side;
  if (hand.events.empty()) return empty;

  constexpr double kUnset = std::numeric_limits<double>::infinity();
  const double impossible = model.weights.impossible;
  std::vector<double> best(hand.candidates.size(), kUnset);
  std::vector<int> back(hand.candidates.size(), -1);
  std::vector<int> chosen(hand.events.size(), -1);
  const std::size_t count = hand.events.size();

  for (std::size_t e = 0; e < count; ++e) {
    const std::size_t stop = std::min(count, e + static_cast<std::size_t>(lookahead));
    // Window DP from the chosen candidate of e-1.
    for (std::size_t w = e; w < stop; ++w) {
      const HandEvent& event = hand.events[w];
      bool any = false;
      for (int pass = 0; pass < 2 && !any; ++pass) {
        const bool check_held = pass == 0;
        for (int b = event.cand_begin; b < event.cand_end; ++b) {
          const Candidate& cb = hand.candidates[static_cast<std::size_t>(b)];
          double best_cost = kUnset;
          int best_prev = -1;
          if (w == 0) {
            best_cost = 0.0;
          } else {
            const HandEvent& prev = hand.events[w - 1];
            for (int a = prev.cand_begin; a < prev.cand_end; ++a) {
              if (w == e && a != chosen[e - 1]) continue;
              const double base = w == e ? 0.0 : best[static_cast<std::size_t>(a)];
              const Candidate& ca = hand.candidates[static_cast<std::size_t>(a)];
              if (base == kUnset || (check_held && !held_compatible(ca, cb))) continue;
              double t = transition_cost(ca.shape, cb.shape, event.dt_s, side, model);
              if (std::isinf(t)) t = impossible;
              if (base + t < best_cost) best_cost = base + t, best_prev = a;
            }
          }
          best[static_cast<std::size_t>(b)] = kUnset;
          if (w == 0 || best_prev >= 0) {
            best[static_cast<std::size_t>(b)] = best_cost + cb.strike;
            back[static_cast<std::size_t>(b)] = best_prev;
            any = true;
          }
        }
      }
    }
    const HandEvent& tail = hand.events[stop - 1];
    int pick = -1;
    for (int c = tail.cand_begin; c < tail.cand_end; ++c) {
      if (pick < 0 || best[static_cast<std::size_t>(c)] < best[static_cast<std::size_t>(pick)])
        pick = c;
    }
    for (std::size_t w = stop - 1; w > e; --w) pick = back[static_cast<std::size_t>(pick)];
    chosen[e] = pick;
  }
  return finish_plan(hand, chosen, notes, model);
}

}  // namespace tutti::fingering_planner
