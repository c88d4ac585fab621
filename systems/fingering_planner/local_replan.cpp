// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/local_replan.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include <tutti/fingering_planner/event_dp.hpp>
#include <tutti/fingering_planner/hand_events.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::HandCorridor;

namespace {

// Events agreeing with the previous plan at each edge of the window before it is accepted.
constexpr int kSettledEvents = 8;
constexpr int kFirstMargin = 8;  // events searched on each side of the edits at first

// The candidate of every event that reproduces the previous fingers (-1 where none does: the
// edit ruled it out, or the event's keys or held notes changed).
std::vector<int> previous_candidates(const PreparedHand& hand, std::span<const int> fingers) {
  std::vector<int> slot_finger(hand.slots.size(), 0);
  std::vector<int> chosen(hand.events.size(), -1);
  for (std::size_t e = 0; e < hand.events.size(); ++e) {
    const HandEvent& event = hand.events[e];
    for (int i = event.note_begin; i < event.note_end; ++i) {
      const auto note = static_cast<std::size_t>(hand.event_notes[static_cast<std::size_t>(i)]);
      slot_finger[static_cast<std::size_t>(hand.note_slot[note])] = fingers[note];
    }
    for (int s = event.slot_begin; s < event.slot_end; ++s) {
      const HandSlot& slot = hand.slots[static_cast<std::size_t>(s)];
      if (slot.held_from >= 0) {
        slot_finger[static_cast<std::size_t>(s)] =
            slot_finger[static_cast<std::size_t>(slot.held_from)];
      }
    }
    for (int c = event.cand_begin; c < event.cand_end && chosen[e] < 0; ++c) {
      const Candidate& cand = hand.candidates[static_cast<std::size_t>(c)];
      bool same = true;
      for (int s = event.slot_begin; s < event.slot_end && same; ++s) {
        const HandSlot& slot = hand.slots[static_cast<std::size_t>(s)];
        same = cand.finger[static_cast<std::size_t>(slot.local)] ==
               slot_finger[static_cast<std::size_t>(s)];
      }
      if (same) chosen[e] = c;
    }
  }
  return chosen;
}

bool settled(const std::vector<int>& now, const std::vector<int>& before, int first, int last,
             int count) {
  const int events = static_cast<int>(now.size());
  auto agree = [&](int from, int to) {
    for (int e = std::max(from, 0); e <= std::min(to, events - 1); ++e) {
      if (now[static_cast<std::size_t>(e)] != before[static_cast<std::size_t>(e)]) return false;
    }
    return true;
  };
  const bool left = first == 0 || agree(first, first + count - 1);
  const bool right = last == events - 1 || agree(last - count + 1, last);
  return left && right;
}

}  // namespace

Result<LocalReplan> replan_hand_locally(std::span<const PlanNote> notes, music::Hand side,
                                        const FingeringModel& model, const HandPlan& previous,
                                        std::span<const int> edited,
                                        std::span<const HandCorridor> other_hand) {
  if (previous.fingers.size() != notes.size()) {
    return Error{"re-plan: the previous plan has " + std::to_string(previous.fingers.size()) +
                 " fingers for " + std::to_string(notes.size()) + " notes"};
  }
  for (int index : edited) {
    if (index < 0 || static_cast<std::size_t>(index) >= notes.size()) {
      return Error{"re-plan: edited note " + std::to_string(index) + " is not one of the " +
                   std::to_string(notes.size()) + " notes"};
    }
  }
  for (int finger : previous.fingers) {
    if (finger < 1 || finger > 5)
      return Error{"re-plan: the previous plan has a note without a finger"};
  }
  auto prepared = prepare_hand(notes, side, model, other_hand);
  if (!prepared) return prepared.error();
  const PreparedHand& hand = *prepared;
  const int events = static_cast<int>(hand.events.size());

  LocalReplan out;
  out.event_count = events;
  std::vector<int> before = previous_candidates(hand, previous.fingers);
  // Events that must be searched again: those the edit touched and those whose previous choice
  // is no longer admissible.
  std::vector<int> note_event(notes.size(), 0);
  for (int e = 0; e < events; ++e) {
    const HandEvent& event = hand.events[static_cast<std::size_t>(e)];
    for (int i = event.note_begin; i < event.note_end; ++i) {
      note_event[static_cast<std::size_t>(hand.event_notes[static_cast<std::size_t>(i)])] = e;
    }
  }
  int dirty_first = events;
  int dirty_last = -1;
  for (int index : edited) {
    const int e = note_event[static_cast<std::size_t>(index)];
    dirty_first = std::min(dirty_first, e);
    dirty_last = std::max(dirty_last, e);
  }
  for (int e = 0; e < events; ++e) {
    if (before[static_cast<std::size_t>(e)] >= 0) continue;
    dirty_first = std::min(dirty_first, e);
    dirty_last = std::max(dirty_last, e);
  }

  std::vector<int> chosen = before;
  std::vector<Diagnostic> searched_diagnostics;
  if (dirty_last >= 0) {
    for (int margin = kFirstMargin;; margin *= 2) {
      const int first = std::max(0, dirty_first - margin);
      const int last = std::min(events - 1, dirty_last + margin);
      chosen = before;
      searched_diagnostics.clear();
      const EventRange range{first, last,
                             first > 0 ? before[static_cast<std::size_t>(first - 1)] : -1,
                             last + 1 < events ? before[static_cast<std::size_t>(last + 1)] : -1};
      solve_event_range(hand, model, range, chosen, searched_diagnostics);
      out.searched_first_event = first;
      out.searched_last_event = last;
      out.whole_hand = first == 0 && last == events - 1;
      if (out.whole_hand || settled(chosen, before, first, last, kSettledEvents)) break;
    }
  }

  out.plan = finish_plan(hand, chosen, notes, model);
  // Diagnostics of the search: the new ones inside the window, the previous ones outside it.
  const double window_start =
      dirty_last >= 0 ? hand.events[static_cast<std::size_t>(out.searched_first_event)].onset_s
                      : 0.0;
  const double window_end =
      dirty_last >= 0 ? hand.events[static_cast<std::size_t>(out.searched_last_event)].onset_s
                      : -1.0;
  for (Diagnostic& d : searched_diagnostics) out.plan.diagnostics.push_back(std::move(d));
  for (const Diagnostic& d : previous.diagnostics) {
    const bool inside = d.time_s >= window_start && d.time_s <= window_end;
    if (d.kind == DiagnosticKind::held_released && d.notes.empty() && !inside) {
      out.plan.diagnostics.push_back(d);
      ++out.kept_diagnostics;
    }
  }

  bool any_changed = false;
  for (std::size_t i = 0; i < notes.size(); ++i) {
    if (out.plan.fingers[i] == previous.fingers[i]) continue;
    ++out.changed_notes;
    const double t = notes[i].onset_s;
    out.first_changed_s = any_changed ? std::min(out.first_changed_s, t) : t;
    out.last_changed_s = any_changed ? std::max(out.last_changed_s, t) : t;
    any_changed = true;
  }
  return out;
}

}  // namespace tutti::fingering_planner
