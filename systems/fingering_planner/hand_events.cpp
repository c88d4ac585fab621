// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/hand_events.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

#include <tutti/fingering_planner/other_hand_cost.hpp>
#include <tutti/music/pitch.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::FingerRange;
using piano_model::HandCorridor;
using piano_model::Keyboard;

namespace {

// Finger (1..5) of the i-th lowest slot for a mask of fingers, per hand side.
struct MaskTable {
  std::array<std::array<std::int8_t, 5>, 32> right{};
  std::array<std::array<std::int8_t, 5>, 32> left{};
  std::array<std::vector<std::uint8_t>, 6> by_count;
  MaskTable() {
    for (unsigned mask = 0; mask < 32; ++mask) {
      int n = 0;
      for (int f = 0; f < 5; ++f) {
        if (mask & (1u << f))
          right[mask][static_cast<std::size_t>(n++)] = static_cast<std::int8_t>(f + 1);
      }
      for (int i = 0; i < n; ++i) {
        left[mask][static_cast<std::size_t>(i)] = right[mask][static_cast<std::size_t>(n - 1 - i)];
      }
      by_count[static_cast<std::size_t>(std::popcount(mask))].push_back(
          static_cast<std::uint8_t>(mask));
    }
  }
};
const MaskTable kMasks;

std::string key_list(std::span<const int> note_indices, std::span<const PlanNote> notes) {
  std::string text;
  for (int i : note_indices) {
    text += (text.empty() ? "" : " ") + music::pitch_name(notes[static_cast<std::size_t>(i)].key);
  }
  return text;
}

std::string at_time(double t) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "at %.3f s: ", t);
  return buffer;
}

}  // namespace

const char* diagnostic_kind_name(DiagnosticKind kind) {
  switch (kind) {
    case DiagnosticKind::too_many_notes:
      return "too_many_notes";
    case DiagnosticKind::unreachable_span:
      return "unreachable_span";
    case DiagnosticKind::held_released:
      return "held_released";
    case DiagnosticKind::pin_conflict:
      return "pin_conflict";
    case DiagnosticKind::impossible_transition:
      return "impossible_transition";
  }
  return "unknown";
}

Result<PreparedHand> prepare_hand(std::span<const PlanNote> notes, music::Hand side,
                                  const FingeringModel& model,
                                  std::span<const HandCorridor> other_hand) {
  const Keyboard& keyboard = model.keyboard;
  const CostWeights& w = model.weights;
  for (std::size_t i = 0; i < notes.size(); ++i) {
    const PlanNote& n = notes[i];
    const std::string where = "note " + std::to_string(i) + ": ";
    if (!keyboard.contains(n.key)) {
      return Error{where + "key " + std::to_string(n.key) + " is not on the keyboard (" +
                   std::to_string(keyboard.lowest_key()) + ".." +
                   std::to_string(keyboard.highest_key()) + ")"};
    }
    if (!std::isfinite(n.onset_s) || !std::isfinite(n.offset_s) || n.offset_s < n.onset_s) {
      return Error{where + "times must be finite with offset >= onset"};
    }
    if (n.pin < 0 || n.pin > 5) return Error{where + "pinned finger must be 0..5"};
  }

  PreparedHand hand;
  hand.side = side;
  hand.note_slot.assign(notes.size(), -1);
  std::vector<int> order(notes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const PlanNote& x = notes[static_cast<std::size_t>(a)];
    const PlanNote& y = notes[static_cast<std::size_t>(b)];
    return x.onset_s != y.onset_s ? x.onset_s < y.onset_s : x.key < y.key;
  });
  hand.events.reserve(notes.size());
  hand.slots.reserve(notes.size() + notes.size() / 2);
  hand.event_notes.reserve(notes.size());
  hand.candidates.reserve(notes.size() * 5);

  auto diag = [&](DiagnosticKind kind, const HandEvent& event, std::string why) {
    Diagnostic d;
    d.kind = kind;
    d.time_s = event.onset_s;
    d.notes.assign(hand.event_notes.begin() + event.note_begin,
                   hand.event_notes.begin() + event.note_end);
    d.message = at_time(event.onset_s) + key_list(d.notes, notes) + ": " + std::move(why);
    hand.diagnostics.push_back(std::move(d));
  };

  std::vector<HandSlot> fresh;  // this event's new slots, reused
  std::vector<int> fresh_notes_begin;
  std::vector<HandSlot> live;
  std::vector<int> slot_of_fresh;
  double previous_onset = 0.0;
  for (std::size_t start = 0; start < order.size();) {
    const double onset = notes[static_cast<std::size_t>(order[start])].onset_s;
    std::size_t stop = start;
    while (stop < order.size() &&
           notes[static_cast<std::size_t>(order[stop])].onset_s - onset <= w.chord_tolerance_s) {
      ++stop;
    }
    HandEvent event;
    event.onset_s = onset;
    event.tonic = notes[static_cast<std::size_t>(order[start])].tonic;
    event.note_begin = static_cast<int>(hand.event_notes.size());
    for (std::size_t i = start; i < stop; ++i) hand.event_notes.push_back(order[i]);
    event.note_end = static_cast<int>(hand.event_notes.size());
    // Keys are sorted within the event (ties broken by onset then key: re-sort by key).
    std::sort(
        hand.event_notes.begin() + event.note_begin, hand.event_notes.end(), [&](int a, int b) {
          return notes[static_cast<std::size_t>(a)].key < notes[static_cast<std::size_t>(b)].key;
        });

    // New slots: one per distinct key.
    fresh.clear();
    for (int i = event.note_begin; i < event.note_end; ++i) {
      const PlanNote& n =
          notes[static_cast<std::size_t>(hand.event_notes[static_cast<std::size_t>(i)])];
      if (fresh.empty() || fresh.back().hi_key != n.key) {
        HandSlot slot;
        slot.lo_key = slot.hi_key = n.key;
        slot.offset_s = n.offset_s;
        slot.pin = n.pin;
        fresh.push_back(slot);
      } else {
        HandSlot& slot = fresh.back();
        slot.offset_s = std::max(slot.offset_s, n.offset_s);
        if (n.pin != 0 && slot.pin != 0 && n.pin != slot.pin) {
          diag(DiagnosticKind::pin_conflict, event, "one key pinned to two fingers");
        } else if (n.pin != 0) {
          slot.pin = n.pin;
        }
      }
    }
    if (fresh.size() > 5) {
      diag(DiagnosticKind::too_many_notes, event,
           std::to_string(fresh.size()) + " keys at once; neighbouring keys share a finger");
      while (fresh.size() > 5) {  // merge the two closest neighbours
        std::size_t best = 0;
        double best_gap = 1e300;
        for (std::size_t i = 0; i + 1 < fresh.size(); ++i) {
          const double gap = keyboard.x_mm(fresh[i + 1].lo_key) - keyboard.x_mm(fresh[i].hi_key);
          if (gap < best_gap) best_gap = gap, best = i;
        }
        fresh[best].hi_key = fresh[best + 1].hi_key;
        fresh[best].offset_s = std::max(fresh[best].offset_s, fresh[best + 1].offset_s);
        if (fresh[best].pin == 0) fresh[best].pin = fresh[best + 1].pin;
        fresh.erase(fresh.begin() + static_cast<std::ptrdiff_t>(best) + 1);
      }
    }

    // Held slots: live slots of the previous event still sounding, not re-struck now.
    live.clear();
    double release_s = -1.0;
    if (!hand.events.empty()) {
      const HandEvent& prev = hand.events.back();
      for (int s = prev.slot_begin; s < prev.slot_end; ++s) {
        const HandSlot& old = hand.slots[static_cast<std::size_t>(s)];
        if (!old.alive) continue;
        bool restruck = false;
        for (const HandSlot& f : fresh)
          restruck |= f.lo_key <= old.hi_key && old.lo_key <= f.hi_key;
        if (old.offset_s > onset + w.chord_tolerance_s && !restruck) {
          HandSlot held = old;
          held.held_from = s;
          held.pin = 0;
          live.push_back(held);
        } else if (old.held_from < 0) {
          release_s = std::max(release_s, std::min(old.offset_s, onset));
        }
      }
      const double release_to_attack = release_s < 0 ? 0.0 : onset - release_s;
      event.dt_s = effective_dt(release_to_attack, onset - previous_onset, w);
    }
    if (live.size() + fresh.size() > 5) {
      diag(DiagnosticKind::held_released, event,
           "more than 5 keys down; the earliest-ending held keys no longer constrain the hand");
      std::sort(live.begin(), live.end(),
                [](const HandSlot& a, const HandSlot& b) { return a.offset_s > b.offset_s; });
      live.resize(5 - fresh.size());
    }
    for (const HandSlot& f : fresh) live.push_back(f);
    std::sort(live.begin(), live.end(),
              [](const HandSlot& a, const HandSlot& b) { return a.lo_key < b.lo_key; });

    // Candidates; fall back step by step: ignore pins, release held keys, accept no reach.
    bool use_pins = true;
    for (;;) {
      event.slot_begin = static_cast<int>(hand.slots.size());
      for (std::size_t i = 0; i < live.size(); ++i) {
        live[i].local = static_cast<int>(i);
        hand.slots.push_back(live[i]);
      }
      event.slot_end = static_cast<int>(hand.slots.size());
      event.cand_begin = static_cast<int>(hand.candidates.size());
      const std::size_t k = live.size();
      bool any_reachable = false;
      for (std::uint8_t mask : kMasks.by_count[k]) {
        const auto& fingers = side == music::Hand::left ? kMasks.left[mask] : kMasks.right[mask];
        bool ok = true;
        if (use_pins) {
          for (std::size_t i = 0; i < k; ++i)
            ok = ok && (live[i].pin == 0 || live[i].pin == fingers[i]);
        }
        if (!ok) continue;
        Candidate c;
        c.finger = fingers;
        EventFingering& shape = c.shape;
        shape.lo_mm = -1e300;
        shape.hi_mm = 1e300;
        for (std::size_t i = 0; i < k; ++i) {
          const int f = fingers[i];
          const auto fi = static_cast<std::size_t>(f - 1);
          const FingerRange& range = model.hand.range(side, f);
          const double x_lo = keyboard.x_mm(live[i].lo_key);
          const double x_hi = keyboard.x_mm(live[i].hi_key);
          shape.lo_mm = std::max(shape.lo_mm, x_hi - range.hi_mm);
          shape.hi_mm = std::min(shape.hi_mm, x_lo - range.lo_mm);
          shape.down = static_cast<std::uint8_t>(shape.down | (1u << fi));
          if (live[i].held_from < 0)
            shape.struck = static_cast<std::uint8_t>(shape.struck | (1u << fi));
          const int key = side == music::Hand::left ? live[i].hi_key : live[i].lo_key;
          shape.key[fi] = static_cast<std::int16_t>(key);
          shape.x_mm[fi] = static_cast<float>(0.5 * (x_lo + x_hi));
        }
        any_reachable = any_reachable || shape.lo_mm <= shape.hi_mm;
        c.strike = strike_cost(shape, model, event.tonic);
        hand.candidates.push_back(c);
      }
      event.cand_end = static_cast<int>(hand.candidates.size());
      const bool empty = event.cand_end == event.cand_begin;
      bool has_held = false;
      for (const HandSlot& s : live) has_held |= s.held_from >= 0;
      if (empty && use_pins) {
        diag(DiagnosticKind::pin_conflict, event,
             "pinned fingers cannot all be used; pins ignored");
        use_pins = false;
      } else if (!any_reachable && has_held) {
        diag(DiagnosticKind::held_released, event,
             "held keys and new keys are out of reach together; held keys released");
        std::erase_if(live, [](const HandSlot& s) { return s.held_from >= 0; });
      } else {
        if (!any_reachable) {
          event.unreachable = true;
          diag(DiagnosticKind::unreachable_span, event,
               "no finger assignment reaches every key; the closest one is used");
          for (int c = event.cand_begin; c < event.cand_end; ++c) {
            Candidate& cand = hand.candidates[static_cast<std::size_t>(c)];
            const double missing = cand.shape.lo_mm - cand.shape.hi_mm;
            cand.strike += w.unreachable * missing / keyboard.white_key_width_mm();
            const double mid = 0.5 * (cand.shape.lo_mm + cand.shape.hi_mm);
            cand.shape.lo_mm = cand.shape.hi_mm = mid;
          }
        } else {
          // Unreachable candidates are dropped when a reachable one exists.
          auto first = hand.candidates.begin() + event.cand_begin;
          auto last = std::remove_if(first, hand.candidates.end(), [](const Candidate& c) {
            return c.shape.lo_mm > c.shape.hi_mm;
          });
          hand.candidates.erase(last, hand.candidates.end());
          event.cand_end = static_cast<int>(hand.candidates.size());
        }
        break;
      }
      hand.slots.resize(static_cast<std::size_t>(event.slot_begin));
      hand.candidates.resize(static_cast<std::size_t>(event.cand_begin));
    }

    // Mark slots of the previous event that were released (not continued).
    if (!hand.events.empty()) {
      const HandEvent& prev = hand.events.back();
      // Held signatures: fingers of held slots now, and of their sources in the previous event.
      int shift = 0;
      for (int s = event.slot_begin; s < event.slot_end; ++s) {
        const HandSlot& slot = hand.slots[static_cast<std::size_t>(s)];
        if (slot.held_from < 0) continue;
        const auto cur_local = static_cast<std::size_t>(slot.local);
        const auto prev_local =
            static_cast<std::size_t>(hand.slots[static_cast<std::size_t>(slot.held_from)].local);
        for (int c = event.cand_begin; c < event.cand_end; ++c) {
          Candidate& cand = hand.candidates[static_cast<std::size_t>(c)];
          cand.held_sig =
              static_cast<std::uint16_t>(cand.held_sig | (cand.finger[cur_local] << shift));
        }
        for (int c = prev.cand_begin; c < prev.cand_end; ++c) {
          Candidate& cand = hand.candidates[static_cast<std::size_t>(c)];
          cand.next_sig =
              static_cast<std::uint16_t>(cand.next_sig | (cand.finger[prev_local] << shift));
        }
        shift += 3;
      }
    }

    // Note -> slot where it is struck.
    for (int i = event.note_begin; i < event.note_end; ++i) {
      const int note = hand.event_notes[static_cast<std::size_t>(i)];
      const int key = notes[static_cast<std::size_t>(note)].key;
      for (int s = event.slot_begin; s < event.slot_end; ++s) {
        const HandSlot& slot = hand.slots[static_cast<std::size_t>(s)];
        if (slot.held_from < 0 && slot.lo_key <= key && key <= slot.hi_key) {
          hand.note_slot[static_cast<std::size_t>(note)] = s;
          break;
        }
      }
    }
    previous_onset = onset;
    hand.events.push_back(event);
    start = stop;
  }

  // Corridor ends: the next onset, or the last release when the keys are let go earlier.
  for (std::size_t e = 0; e < hand.events.size(); ++e) {
    HandEvent& event = hand.events[e];
    double release = event.onset_s;
    for (int s = event.slot_begin; s < event.slot_end; ++s) {
      release = std::max(release, hand.slots[static_cast<std::size_t>(s)].offset_s);
    }
    event.end_s =
        e + 1 < hand.events.size() ? std::min(release, hand.events[e + 1].onset_s) : release;
    event.end_s = std::max(event.end_s, event.onset_s);
  }
  add_other_hand_cost(hand, other_hand, model);
  return hand;
}

HandPlan finish_plan(const PreparedHand& hand, std::span<const int> chosen,
                     std::span<const PlanNote> notes, const FingeringModel& model) {
  HandPlan plan;
  plan.hand = hand.side;
  plan.fingers.assign(notes.size(), 0);
  plan.diagnostics = hand.diagnostics;
  plan.corridors.reserve(hand.events.size());
  const Candidate* previous = nullptr;
  for (std::size_t e = 0; e < hand.events.size(); ++e) {
    const HandEvent& event = hand.events[e];
    const Candidate& cand = hand.candidates[static_cast<std::size_t>(chosen[e])];
    HandCorridor corridor{event.onset_s, event.end_s, cand.shape.lo_mm, cand.shape.hi_mm};
    for (int s = event.slot_begin; s < event.slot_end; ++s) {
      const HandSlot& slot = hand.slots[static_cast<std::size_t>(s)];
      if (!slot.alive) continue;  // let go early: no finger stays on it
      const double lo = model.keyboard.x_mm(
          std::clamp(slot.lo_key, model.keyboard.lowest_key(), model.keyboard.highest_key()));
      const double hi = model.keyboard.x_mm(
          std::clamp(slot.hi_key, model.keyboard.lowest_key(), model.keyboard.highest_key()));
      corridor.keys_lo_mm = corridor.keys_known ? std::min(corridor.keys_lo_mm, lo) : lo;
      corridor.keys_hi_mm = corridor.keys_known ? std::max(corridor.keys_hi_mm, hi) : hi;
      corridor.keys_known = true;
    }
    plan.corridors.push_back(corridor);
    // The transition cost priced a move between disjoint areas over the effective time dt_s
    // (which may count an early release, release_fraction). The corridor must end when that
    // move starts, or the hand path would be asked to jump in no time.
    if (previous != nullptr && e > 0) {
      const bool disjoint = std::min(previous->shape.hi_mm, cand.shape.hi_mm) <
                            std::max(previous->shape.lo_mm, cand.shape.lo_mm);
      HandCorridor& before = plan.corridors[e - 1];
      if (disjoint && event.dt_s > 0) {
        before.end_s = std::max(before.start_s, std::min(before.end_s, event.onset_s - event.dt_s));
      }
    }
    plan.total_cost += cand.strike;
    if (previous != nullptr) {
      const double t = transition_cost(previous->shape, cand.shape, event.dt_s, hand.side, model);
      if (std::isinf(t)) {
        ++plan.impossible_transitions;
        Diagnostic d;
        d.kind = DiagnosticKind::impossible_transition;
        d.time_s = event.onset_s;
        d.notes.assign(hand.event_notes.begin() + event.note_begin,
                       hand.event_notes.begin() + event.note_end);
        d.message = at_time(event.onset_s) + key_list(d.notes, notes) +
                    ": no finite-cost move from the previous notes (same finger again or a jump "
                    "with no time to travel)";
        plan.diagnostics.push_back(std::move(d));
      } else {
        plan.total_cost += t;
      }
    }
    previous = &cand;
    for (int i = event.note_begin; i < event.note_end; ++i) {
      const auto note = static_cast<std::size_t>(hand.event_notes[static_cast<std::size_t>(i)]);
      const HandSlot& slot = hand.slots[static_cast<std::size_t>(hand.note_slot[note])];
      plan.fingers[note] = cand.finger[static_cast<std::size_t>(slot.local)];
    }
  }
  std::stable_sort(plan.diagnostics.begin(), plan.diagnostics.end(),
                   [](const Diagnostic& a, const Diagnostic& b) { return a.time_s < b.time_s; });
  return plan;
}

}  // namespace tutti::fingering_planner
