// SPDX-License-Identifier: MIT
#pragma once
// Re-planning one hand after an edit (a finger pinned or unpinned, in the editor or a file)
// without disturbing the rest of the piece: only a window of events around the edited notes is
// searched again, entered from and left to the previous plan's unchanged choices. The window
// starts small and doubles until the new fingering agrees with the previous one at both of its
// edges (the change has died out), or covers the whole hand.
//
// Result: optimal among fingerings that keep every event outside the window as it was; the
// notes outside [first_changed_note, last_changed_note] keep their fingers by construction.
// The tests compare the cost with a full re-plan of the same pins on real pieces.

#include <span>

#include <tutti/core/result.hpp>
#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/fingering_planner/hand_plan.hpp>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::HandCorridor;

struct LocalReplan {
  HandPlan plan;
  int searched_first_event = 0;  // the window searched again (events, inclusive); empty when
  int searched_last_event = -1;  // nothing needed re-planning
  int event_count = 0;           // events of the hand
  int changed_notes = 0;         // notes whose finger differs from the previous plan
  double first_changed_s = 0.0;  // onset span of the changed notes (0, 0 when none changed)
  double last_changed_s = 0.0;
  bool whole_hand = false;  // the window grew to the whole hand
  // plan.diagnostics ends with this many of `previous`'s, kept as they were because they are
  // outside the window (the search's own reports of held keys released there).
  int kept_diagnostics = 0;
};

// `notes` are the previous plan's input with only the pins of `edited` (indices into notes)
// changed; `previous` is that plan (its fingers must have one entry per note). Errors: invalid
// notes, or a previous plan of another size.
Result<LocalReplan> replan_hand_locally(std::span<const PlanNote> notes, music::Hand side,
                                        const FingeringModel& model, const HandPlan& previous,
                                        std::span<const int> edited,
                                        std::span<const HandCorridor> other_hand = {});

}  // namespace tutti::fingering_planner
