// SPDX-License-Identifier: MIT
#pragma once
// What `tutti fingering` writes, one function per format. All outputs are deterministic (no
// timings): the same input gives the same bytes.
//
// MIDI encoding of the fingering (MIDI has no fingering event): one lyric meta event (FF 05) per
// note at its note-on tick, text "<hand><finger>:<key>", e.g. "RH3:64" (right hand, middle
// finger, MIDI key 64) or "LH5:48". The writer puts texts in the conductor track (track 0), so
// the key disambiguates a chord; parse_finger_label reads one back.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/music/score.hpp>
#include <tutti/piano_performance/performance_plan.hpp>

namespace tutti::cli {

// The score with Note::finger and Note::hand from the plan (substitutions cleared).
music::Score fingered_score(const music::Score& score, const fingering_planner::ScorePlan& plan);

// {"file", "notes": [{index, pitch, onset_s, offset_s, hand, finger}], "hands": {right, left}}.
std::string fingering_json(const music::Score& fingered, const piano_performance::PerformanceReport& r);

// One line per note: index, onset, key name, hand, finger.
std::string fingering_listing(const music::Score& fingered);

// "RH3:64" / "LH1:48"; hand unknown or finger 0 -> "".
std::string finger_label(music::Hand hand, int finger, int key);
struct FingerLabel {
  music::Hand hand = music::Hand::unknown;
  int finger = 0;
  int key = 0;
};
std::optional<FingerLabel> parse_finger_label(std::string_view text);

// Reads the labels of a MIDI file tutti wrote back into Note::finger / Note::hand (notes matched
// by onset tick and key, first come first served; notes already fingered are left alone).
// Returns how many notes got a finger.
int apply_finger_labels(music::Score& score);

// The MIDI file with one finger label per note (see above); labels already in the score (an
// input tutti wrote) are replaced, not duplicated.
std::vector<std::uint8_t> fingering_midi(const music::Score& fingered);

}  // namespace tutti::cli
