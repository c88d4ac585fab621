// SPDX-License-Identifier: MIT
#pragma once
// Where grace notes sound. MusicXML gives them no duration, so the reader decides:
//
//  - Default (and steal-time-following): on the beat. The graces start at the principal note's
//    onset and the principal starts later by their total, keeping its offset; after a rest they
//    start at the rest's onset.
//  - Leading graces marked steal-time-previous (after-graces), and graces with no note left in
//    their voice at the end of a part: after the previous note of the voice. They end where
//    that note ended (at the latest where the next note starts) and the note (its whole chord)
//    is cut short to make room.
//  - Each grace (a grace chord counts once) lasts a 32nd note (ticks_per_quarter / 8), or
//    steal-time-*'s percentage of the host note split evenly; in every case the graces take at
//    most half of the note they steal from, so no duration goes negative and the graces never
//    overlap the note they lead to.

#include <cstdint>
#include <optional>

namespace tutti::music::musicxml {

// Total ticks of a run of `slots` graces stealing from a note of `host_ticks`.
// `steal_percent` is the steal-time-* attribute when present.
std::int64_t grace_run_ticks(std::int64_t slots, std::int64_t host_ticks,
                             std::optional<double> steal_percent, int ticks_per_quarter);

// Start of slot `index` of `slots` when a run of `total` ticks starts at `start`; slot i spans
// [grace_slot_start(i), grace_slot_start(i + 1)). Overflow-free for any total <= 2^50.
std::int64_t grace_slot_start(std::int64_t start, std::int64_t total, std::int64_t slots,
                              std::int64_t index);

}  // namespace tutti::music::musicxml
