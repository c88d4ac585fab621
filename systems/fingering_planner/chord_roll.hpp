// SPDX-License-Identifier: MIT
#pragma once
// Chords one hand cannot span with the fingers it was given (a tenth for a medium hand: no
// reference point of the hand puts every finger of the chord on its key, hand_model.hpp) are
// rolled, as pianists roll them: the notes struck one after another from the bottom up,
// `step_s` apart, and a note let go just before a note out of its reach strikes, so the hand
// can move on. What is heard keeps the written ends (as if pedalled); the keys go up early.
//
// Planned from a first fingering of the score; the rolled score is then planned again (the same
// fingers pinned) so hand paths and finger strokes follow the roll. A pure function of the
// score, the plan and the model.

#include <vector>

#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/music/score.hpp>

namespace tutti::fingering_planner {

struct RolledNote {
  int note = -1;          // Score::notes index
  double onset_s = 0.0;   // struck (and heard) here, at or after the written onset
  double release_s = 0.0; // the key goes up here, at or before the written offset
};

struct ChordRolls {
  std::vector<RolledNote> notes;  // in Score::notes order
  int chords = 0;                 // chords rolled
  bool empty() const { return notes.empty(); }
};

// `step_s` > 0: the time between two notes of a roll, shortened for short chords so the roll
// ends within half of the chord's shortest note.
ChordRolls plan_chord_rolls(const music::Score& score, const ScorePlan& plan,
                            const FingeringModel& model, double step_s = 0.04);

// Moves the rolled notes' onset_s and offset_s (the key's release) in `score`, whose notes
// are the ones the rolls were planned on.
void apply_chord_rolls(const ChordRolls& rolls, music::Score& score);

}  // namespace tutti::fingering_planner
