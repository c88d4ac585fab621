// SPDX-License-Identifier: MIT
#pragma once
// How close the streaming planner comes to the exact one on a whole score: the score's notes
// are fed in onset order (offsets known, no deadline: only the lookahead limits what each
// decision sees) and the fingers compared note by note with plan_score's exact plan (marks in
// the file not pinned, on either side). Two feeds:
//  - the exact plan's hands (assign_hands): the fingering search alone is compared;
//  - the live split (LiveHandSplit): what a live performance gets, hands and fingers together.
// Costs are the cost model's total for each fingering (plan_hand_exact with every finger pinned;
// an impossible move counts weights.impossible), summed over both hands.

#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/music/score.hpp>

namespace tutti::fingering_planner {

struct HandAgreement {
  int notes = 0;
  int same_finger = 0;
  double streaming_cost = 0.0;
  double exact_cost = 0.0;
};

struct StreamingAgreement {
  int lookahead = 0;
  HandAgreement right;  // exact plan's hands
  HandAgreement left;
  int notes = 0;              // planned notes (both hands)
  int split_same_hand = 0;    // live split: notes on the exact plan's hand
  int split_same_finger = 0;  // live split: same hand and same finger
  double split_cost = 0.0;    // live split: both hands' cost
  // Identical to plan_hand_lookahead(lookahead + 1) on the exact plan's hands, note by note.
  int same_as_lookahead_planner = 0;

  int same_finger() const { return right.same_finger + left.same_finger; }
  double cost_ratio() const {
    const double exact = right.exact_cost + left.exact_cost;
    return exact > 0 ? (right.streaming_cost + left.streaming_cost) / exact : 1.0;
  }
};

// Errors: the planners' (invalid options, lookahead < 0).
Result<StreamingAgreement> measure_streaming_agreement(const music::Score& score,
                                                       const FingeringModel& model, int lookahead);

}  // namespace tutti::fingering_planner
