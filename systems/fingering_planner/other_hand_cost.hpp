// SPDX-License-Identifier: MIT
#pragma once
// The other hand's room: a hand's fingering is priced by how close it puts the hand to where the
// other hand is at the same time. Two hands on neighbouring keys need about a hand's width
// between their middle fingers (CostWeights::other_hand_separation); a fingering that puts this
// hand's area nearer than that to the other hand's corridor (planned first) costs
// CostWeights::other_hand_per_white_key per white key of shortfall. Between two fingerings of
// the same notes this prefers the one that keeps the hand on its own side (a left hand playing
// B3-D4 beside the right hand's C4-D4 trill takes 2-1, not 5-3, which would put its palm under
// the right hand's). The window of an event starts other_hand_lead_s before its onset and ends
// as long after its end: a hand arrives before it strikes, and the other hand arrives before
// this one has left.

#include <span>

#include <tutti/fingering_planner/hand_events.hpp>
#include <tutti/piano_model/hand_corridor.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::HandCorridor;

// Adds the cost to every candidate's strike cost. `other_hand`: the other hand's corridors
// (sorted by time, as planned); empty or a zero weight = nothing changes.
void add_other_hand_cost(PreparedHand& hand, std::span<const HandCorridor> other_hand,
                         const FingeringModel& model);

}  // namespace tutti::fingering_planner
