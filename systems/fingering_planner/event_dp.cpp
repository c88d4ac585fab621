// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/event_dp.hpp>

#include <cmath>
#include <limits>
#include <string>

namespace tutti::fingering_planner {
namespace {

constexpr double kUnset = std::numeric_limits<double>::infinity();

double priced_transition(const Candidate& from, const Candidate& to, const HandEvent& event,
                         music::Hand side, const FingeringModel& model) {
  const double t = transition_cost(from.shape, to.shape, event.dt_s, side, model);
  return std::isinf(t) ? model.weights.impossible : t;
}

}  // namespace

void solve_event_range(const PreparedHand& hand, const FingeringModel& model,
                       const EventRange& range, std::vector<int>& chosen,
                       std::vector<Diagnostic>& diagnostics) {
  if (range.first > range.last) return;
  const auto& events = hand.events;
  const auto& cands = hand.candidates;
  // Costs and back pointers only for the candidates of the range (contiguous in `cands`).
  const int base = events[static_cast<std::size_t>(range.first)].cand_begin;
  const int size = events[static_cast<std::size_t>(range.last)].cand_end - base;
  std::vector<double> best(static_cast<std::size_t>(size), kUnset);
  std::vector<int> back(static_cast<std::size_t>(size), -1);
  auto at = [base](int candidate) { return static_cast<std::size_t>(candidate - base); };

  for (int e = range.first; e <= range.last; ++e) {
    const HandEvent& event = events[static_cast<std::size_t>(e)];
    const bool entering = e == range.first;
    if (entering && range.entry < 0) {
      for (int c = event.cand_begin; c < event.cand_end; ++c) {
        best[at(c)] = cands[static_cast<std::size_t>(c)].strike;
      }
      continue;
    }
    const int prev_begin =
        entering ? range.entry : events[static_cast<std::size_t>(e - 1)].cand_begin;
    const int prev_end =
        entering ? range.entry + 1 : events[static_cast<std::size_t>(e - 1)].cand_end;
    bool any = false;
    for (int pass = 0; pass < 2 && !any; ++pass) {
      const bool check_held = pass == 0;  // second pass: held fingers could not be kept
      for (int b = event.cand_begin; b < event.cand_end; ++b) {
        const Candidate& cb = cands[static_cast<std::size_t>(b)];
        double best_cost = kUnset;
        int best_prev = -1;
        for (int a = prev_begin; a < prev_end; ++a) {
          const Candidate& ca = cands[static_cast<std::size_t>(a)];
          const double before = entering ? 0.0 : best[at(a)];
          if (before == kUnset || (check_held && !held_compatible(ca, cb))) continue;
          const double total = before + priced_transition(ca, cb, event, hand.side, model);
          if (total < best_cost) best_cost = total, best_prev = a;
        }
        if (best_prev >= 0) {
          best[at(b)] = best_cost + cb.strike;
          back[at(b)] = best_prev;
          any = true;
        }
      }
      if (!any && check_held) {
        Diagnostic d;
        d.kind = DiagnosticKind::held_released;
        d.time_s = event.onset_s;
        d.message = "at " + std::to_string(event.onset_s) +
                    " s: held keys cannot keep their fingers with these new keys; released";
        diagnostics.push_back(std::move(d));
      }
    }
  }

  // The last event: cheapest total, including the move into the fixed exit candidate.
  const HandEvent& last = events[static_cast<std::size_t>(range.last)];
  int pick = -1;
  for (int pass = 0; pass < 2 && pick < 0; ++pass) {
    const bool check_held = pass == 0 && range.exit >= 0;
    double best_total = kUnset;
    for (int c = last.cand_begin; c < last.cand_end; ++c) {
      double total = best[at(c)];
      if (total == kUnset) continue;
      if (range.exit >= 0) {
        const Candidate& out = cands[static_cast<std::size_t>(range.exit)];
        if (check_held && !held_compatible(cands[static_cast<std::size_t>(c)], out)) continue;
        total +=
            priced_transition(cands[static_cast<std::size_t>(c)], out,
                              events[static_cast<std::size_t>(range.last + 1)], hand.side, model);
      }
      if (total < best_total) best_total = total, pick = c;
    }
  }
  for (int e = range.last; e >= range.first; --e) {
    chosen[static_cast<std::size_t>(e)] = pick;
    if (e > range.first) pick = back[at(pick)];
  }
}

}  // namespace tutti::fingering_planner
