// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/other_hand_cost.hpp>

#include <algorithm>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::HandCorridor;

void add_other_hand_cost(PreparedHand& hand, std::span<const HandCorridor> other_hand,
                         const FingeringModel& model) {
  const CostWeights& w = model.weights;
  if (other_hand.empty() || w.other_hand_per_white_key <= 0.0) return;
  const double white = model.keyboard.white_key_width_mm();
  const double separation_mm = w.other_hand_separation * white;
  // The other hand is to the right of a left hand, to the left of a right hand.
  const bool other_is_above = hand.side == music::Hand::left;
  for (const HandEvent& event : hand.events) {
    const double from_s = event.onset_s - w.other_hand_lead_s;
    const double to_s = std::max(event.end_s, event.onset_s) + w.other_hand_lead_s;
    // Corridors end in order (consecutive ones do not overlap): the first one still open.
    auto it = std::partition_point(other_hand.begin(), other_hand.end(),
                                   [&](const HandCorridor& c) { return c.end_s <= from_s; });
    bool any = false;
    double nearest = 0.0;  // the other hand's centre nearest this hand
    for (; it != other_hand.end() && it->start_s < to_s; ++it) {
      const double centre = 0.5 * (it->lo_mm + it->hi_mm);
      nearest = !any ? centre : other_is_above ? std::min(nearest, centre) : std::max(nearest, centre);
      any = true;
    }
    if (!any) continue;
    for (int c = event.cand_begin; c < event.cand_end; ++c) {
      Candidate& cand = hand.candidates[static_cast<std::size_t>(c)];
      const double centre = 0.5 * (cand.shape.lo_mm + cand.shape.hi_mm);
      const double shortfall =
          other_is_above ? centre - (nearest - separation_mm) : (nearest + separation_mm) - centre;
      if (shortfall > 0.0) cand.strike += w.other_hand_per_white_key * shortfall / white;
    }
  }
}

}  // namespace tutti::fingering_planner
