#include "fingering_planner/plan_score.hpp"

#include <algorithm>
#include <cmath>

#include "fingering_planner/exact_planner.hpp"
#include "fingering_planner/lookahead_planner.hpp"
#include "music/pitch.hpp"

namespace tutti::piano {

Result<HandPlan> plan_hand(std::span<const PlanNote> notes, music::Hand side,
                           const FingeringModel& model, const PlanOptions& options) {
  if (options.mode == PlannerMode::lookahead) {
    return plan_hand_lookahead(notes, side, model, options.lookahead);
  }
  return plan_hand_exact(notes, side, model);
}

int bar_at_beats(const music::Score& score, double beats) {
  double bar_start = 0.0;
  int bar = 1;
  double bar_length = 4.0;
  for (const music::TimeSignature& ts : score.time_signatures) {
    const double at = score.tempo_map.beats_at(static_cast<double>(ts.tick));
    if (at > beats) break;
    const double bars = std::floor((at - bar_start) / bar_length + 1e-9);
    bar += static_cast<int>(bars);
    bar_start += bars * bar_length;
    if (at > bar_start + 1e-9) {  // a change mid-bar starts a new bar
      ++bar;
      bar_start = at;
    }
    bar_length = ts.denominator > 0 ? 4.0 * ts.numerator / ts.denominator : 4.0;
  }
  return bar + static_cast<int>(std::floor((beats - bar_start) / bar_length + 1e-9));
}

Result<ScorePlan> plan_score(const music::Score& score, const FingeringModel& model,
                             const PlanOptions& options) {
  ScorePlan out;
  const HandAssignment assignment = assign_hands(score, model);
  out.hands = assignment.hand;
  out.fingers.assign(score.notes.size(), 0);
  std::vector<Diagnostic> clamped;
  for (music::Hand side : {music::Hand::right, music::Hand::left}) {
    std::vector<int>& indices = side == music::Hand::right ? out.right_notes : out.left_notes;
    std::vector<PlanNote> notes;
    for (std::size_t i = 0; i < score.notes.size(); ++i) {
      if (assignment.hand[i] != side) continue;
      const music::Note& n = score.notes[i];
      PlanNote p;
      p.key = std::clamp(n.pitch, model.keyboard.lowest_key(), model.keyboard.highest_key());
      if (p.key != n.pitch) {
        Diagnostic d;
        d.kind = DiagnosticKind::unreachable_span;
        d.time_s = n.onset_s;
        d.bar = bar_at_beats(score, n.onset_beats);
        d.notes = {static_cast<int>(i)};
        d.message = score.source + ": bar " + std::to_string(d.bar) + ": " +
                    music::pitch_name(n.pitch) + " is off the keyboard; planned as " +
                    music::pitch_name(p.key);
        clamped.push_back(std::move(d));
      }
      p.onset_s = n.onset_s;
      p.offset_s = std::max(n.offset_s, n.onset_s);
      p.pin = options.pins_from_marks && n.finger >= 1 && n.finger <= 5 ? n.finger : 0;
      notes.push_back(p);
      indices.push_back(static_cast<int>(i));
    }
    auto plan = plan_hand(notes, side, model, options);
    if (!plan) return Error{score.source + ": " + plan.error().message};
    for (std::size_t k = 0; k < indices.size(); ++k) {
      out.fingers[static_cast<std::size_t>(indices[k])] = plan->fingers[k];
    }
    for (Diagnostic& d : plan->diagnostics) {
      for (int& note : d.notes) note = indices[static_cast<std::size_t>(note)];
      if (!d.notes.empty()) {
        d.bar =
            bar_at_beats(score, score.notes[static_cast<std::size_t>(d.notes.front())].onset_beats);
      }
      d.message = score.source + ": bar " + std::to_string(d.bar) + " (" +
                  (side == music::Hand::right ? "right" : "left") + " hand) " + d.message;
    }
    (side == music::Hand::right ? out.right : out.left) = std::move(*plan);
  }
  for (Diagnostic& d : clamped) {
    HandPlan& target = out.hands[static_cast<std::size_t>(d.notes.front())] == music::Hand::left
                           ? out.left
                           : out.right;
    target.diagnostics.push_back(std::move(d));
  }
  return out;
}

}  // namespace tutti::piano
