// SPDX-License-Identifier: MIT
#pragma once
// Which hand plays each note of a Score. In order of precedence, per part:
//  1. Note::hand when the file states it (PIG channel 0 = right, 1 = left);
//  2. a part named for a hand ("right"/"left", "R.H."/"L.H.", case-insensitive);
//  3. a part with 2+ staves: staff 1 = right hand, staff 2 and below = left hand;
//  4. otherwise an automatic split of all remaining notes together (every part without hands of
//     its own, e.g. fugue voices on separate tracks), event by event (notes starting together): the
//     keys are cut at one point (low part left, high part right, so hands never cross within an
//     event), choosing the cut that keeps each hand's span reachable and at most 5 keys, keeps each
//     hand near where it was (a far jump counts as an octave), the right hand from middle C up and
//     the left hand below it. Keys a hand still holds count in its span, and no hand strikes a
//     key at or past one the other hand holds (that puts one thumb through the other).
// Percussion parts get Hand::unknown (not planned).
// Then, but for hands a file states: notes struck together that one hand cannot span (wider than
// its reach, or more than five) give their outer notes to the other hand where it is free to take
// them without crossing (HandSource::reach). Last, a key both hands strike at once is played by
// one hand, the one with more of its keys near it then (HandSource::unison). And a note that
// would take its hand across the other (a right-hand G3 under the left hand's held D4-G4) goes to
// the other hand when it can add it at its own outer side (HandSource::crossing); so does a key
// the other hand struck before it and still holds, or let go less than 0.3 s before (the thumbs
// would meet on it).
// Last of all, a passage where the two hands play crowded together (their inner keys less than
// kCrowdedWhiteKeys apart, or crossed) at every onset, and all their keys at each onset fit one
// hand (its reach, five keys), goes to the hand with more of its notes (HandSource::crowded): a
// pianist plays two close lines with one hand rather than the hands inside each other.

#include <vector>

#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/music/score.hpp>

namespace tutti::fingering_planner {

enum class HandSource { file, part_name, staff, automatic, reach, unison, crossing, crowded, none };

struct HandAssignment {
  std::vector<music::Hand> hand;   // per Score::notes entry
  std::vector<HandSource> source;  // why
};

HandAssignment assign_hands(const music::Score& score, const FingeringModel& model);

}  // namespace tutti::fingering_planner
