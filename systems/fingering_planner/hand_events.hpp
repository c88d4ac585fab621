// SPDX-License-Identifier: MIT
#pragma once
// Internal to the planners: one hand's notes turned into events (notes starting together) with
// slots (the keys sounding at the event: struck now or still held) and every admissible finger
// assignment per event (candidates), with their hand areas and strike costs precomputed, so the
// search loops only combine numbers.
//
// Slots of an event are ordered by key; a candidate gives them distinct fingers ordered like the
// keys (right hand: higher key <-> higher finger; left hand reversed), so an event with k slots
// has at most C(5,k) candidates. Held slots must keep the finger they were struck with: a
// candidate's `held_sig` packs those fingers; a transition is allowed when the previous
// candidate's `next_sig` equals it.

#include <cstdint>
#include <span>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/fingering_planner/hand_plan.hpp>
#include <tutti/fingering_planner/transition_cost.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::HandCorridor;

struct HandSlot {
  int lo_key = 0;  // lowest and highest key sharing this finger (equal unless > 5 keys)
  int hi_key = 0;
  int pin = 0;            // required finger, 0 = free
  int held_from = -1;     // slot of the previous event this one continues, -1 = struck now
  double offset_s = 0.0;  // when its last note is released
  int local = -1;         // position among its event's live slots
  bool alive = true;      // false = released from the constraint
};

struct HandEvent {
  double onset_s = 0.0;
  double end_s = 0.0;
  int tonic = -1;     // pitch class of the tonic (first note's PlanNote::tonic), -1 = unknown
  double dt_s = 0.0;  // effective release-to-attack time from the previous event
  int slot_begin = 0, slot_end = 0;
  int note_begin = 0, note_end = 0;  // into PreparedHand::event_notes
  int cand_begin = 0, cand_end = 0;  // into PreparedHand::candidates
  bool unreachable = false;
};

struct Candidate {
  EventFingering shape;
  std::array<std::int8_t, 5> finger{};  // per live slot (local order)
  double strike = 0.0;                  // strike cost (+ unreachable penalty)
  std::uint16_t held_sig = 0;           // fingers of this event's held slots
  std::uint16_t next_sig = 0;           // fingers of the slots the next event holds
};

struct PreparedHand {
  music::Hand side = music::Hand::right;
  std::vector<HandEvent> events;
  std::vector<HandSlot> slots;
  std::vector<int> event_notes;  // input note indices struck at each event
  std::vector<int> note_slot;    // per input note: the slot it was struck in
  std::vector<Candidate> candidates;
  std::vector<Diagnostic> diagnostics;
};

// `other_hand`: the other hand's corridors, planned first; their room is priced into the
// candidates' strike costs (other_hand_cost.hpp). Empty = this hand alone.
Result<PreparedHand> prepare_hand(std::span<const PlanNote> notes, music::Hand side,
                                  const FingeringModel& model,
                                  std::span<const HandCorridor> other_hand = {});

// Turns a choice of one candidate per event into the plan (fingers, corridors, cost, diagnostics).
HandPlan finish_plan(const PreparedHand& hand, std::span<const int> chosen,
                     std::span<const PlanNote> notes, const FingeringModel& model);

// The DP's view of a transition: infinite costs become weights.impossible.
inline bool held_compatible(const Candidate& a, const Candidate& b) {
  return a.next_sig == b.held_sig;
}

}  // namespace tutti::fingering_planner
