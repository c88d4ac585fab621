// SPDX-License-Identifier: MIT
#pragma once
// Names of valve combinations and slide fingerings, both ways: "open", "1-3", "T-2" for valves;
// "3", "T1" for a slide (trigger names, then the position). Used by the data files (preference
// lists, overrides) and by reports.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <tutti/brass_model/instrument.hpp>

namespace tutti::brass_model {

// "open" for no valve; otherwise the valves down joined by '-', side-switching valves first,
// the others in file order ("T-1-2").
std::string combination_name(std::span<const ValveSpec> valves, std::uint8_t mask);
// "open" (or "") → 0; "1-3", "3-1", "T-2" → their mask. nullopt: an unknown or repeated name.
std::optional<std::uint8_t> parse_combination(std::span<const ValveSpec> valves,
                                              std::string_view text);

struct SlideFingering {
  std::uint8_t valves = 0;  // triggers down
  int position = 1;         // 1..
};
// "3" (position 3), "T1" (trigger T down, 1st position), "T-D2" (two triggers).
std::string slide_fingering_name(std::span<const ValveSpec> triggers, std::uint8_t mask,
                                 int position);
// The inverse; nullopt without a position number or with an unknown trigger name.
std::optional<SlideFingering> parse_slide_fingering(std::span<const ValveSpec> triggers,
                                                    std::string_view text);

}  // namespace tutti::brass_model
