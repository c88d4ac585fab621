// SPDX-License-Identifier: MIT
#pragma once
// The text of a <fingering> mark as piano fingers. Editions write a plain finger ("3"), a
// substitution while the key is held ("3-1", "3 1", "3–1", "31") or non-numeric marks (guitar
// "p", "T") that do not concern a pianist.

#include <optional>
#include <string_view>

namespace tutti::music::musicxml {

struct FingeringMark {
  int finger = 0;      // 1..5
  int substitute = 0;  // 1..5, or 0 for none
};

// The first digit 1..5 is the finger, a second one after optional separators (space, '-', '–',
// '_', ',', '/', '~') the substitute. nullopt when the text does not start with a finger.
std::optional<FingeringMark> parse_fingering_text(std::string_view text);

}  // namespace tutti::music::musicxml
