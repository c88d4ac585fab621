// SPDX-License-Identifier: MIT
#pragma once
// Input and output of planning one hand.
//
// Input: PlanNote per note (MIDI key on the keyboard, onset/offset in seconds, optional pinned
// finger). Validated by the planners: key on the keyboard, finite times, offset >= onset,
// pin 0..5; a violation is an Error naming the note index.
//
// Output: a finger for every input note (never a dropped note), the hand's corridor per event
// (the intersection of the chosen fingers' areas, millimetres of keyboard x), the total cost and
// diagnostics for whatever could not be honoured (with the time, the notes and why).

#include <string>
#include <vector>

#include <tutti/music/score.hpp>
#include <tutti/piano_model/hand_corridor.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::HandCorridors;

struct PlanNote {
  int key = 60;  // MIDI key
  double onset_s = 0.0;
  double offset_s = 0.0;  // >= onset_s; the key is held until then (constrains the hand)
  int pin = 0;            // 1..5 = this finger is required, 0 = free
  int tonic = -1;         // pitch class (0 = C .. 11) of the key's tonic here, -1 = unknown
};

enum class DiagnosticKind {
  too_many_notes,         // more than 5 keys at once: neighbouring keys share a finger
  unreachable_span,       // no assignment reaches every key: the least-bad one is used
  held_released,          // a held key's constraint was dropped to make room or reach
  pin_conflict,           // pins that cannot all hold (ignored for this event)
  impossible_transition,  // an infinite-cost move (e.g. same finger on consecutive notes, legato)
};

const char* diagnostic_kind_name(DiagnosticKind kind);

struct Diagnostic {
  DiagnosticKind kind = DiagnosticKind::too_many_notes;
  double time_s = 0.0;
  int bar = 0;             // 1-based bar number when known (score planning), else 0
  std::vector<int> notes;  // indices into the planner's input (or Score::notes for plan_score)
  std::string message;     // one line: "at 12.50 s: 6 keys at once (C4 E4 ...); ..."
};

struct HandPlan {
  music::Hand hand = music::Hand::right;
  std::vector<int> fingers;        // per input note, 1..5
  HandCorridors corridors;         // per event (notes starting together), sorted by time
  double total_cost = 0.0;         // sum of finite costs along the chosen fingering
  int impossible_transitions = 0;  // infinite-cost moves that could not be avoided
  std::vector<Diagnostic> diagnostics;
};

}  // namespace tutti::fingering_planner
