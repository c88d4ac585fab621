// SPDX-License-Identifier: MIT
#pragma once
// Standard MIDI File writer: format 1, the score's own PPQ (SMPTE scores, and PPQ beyond the 15
// bits a header holds, are written as PPQ 480 at their tempo map), a conductor track (tempo, time
// and key signatures, markers and the other texts) then one track per part (name, program, notes,
// sustain pedal). Reading the result back gives the same
// notes, tempo map and parts.
//
// What a round trip cannot keep, because MIDI cannot say it:
//  - part ids and track numbers (tracks are renumbered: conductor first), and parts without
//    notes (a MIDI part exists only through its notes);
//  - two notes of one key in one part where the later-starting one ends first: readers pair
//    them first in, first out, so their ends are swapped;
//  - overlapping pedal spans of one part (merged), denominators that are not powers of two
//    (rounded down to one), texts of kind `other` (written as plain text).
// Parts without a MIDI channel get one: 9 for percussion, the other fifteen in turn otherwise.

#include <cstdint>
#include <filesystem>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>

namespace tutti::music {

std::vector<std::uint8_t> write_midi(const Score& score);
Status write_midi_file(const Score& score, const std::filesystem::path& path);

}  // namespace tutti::music
