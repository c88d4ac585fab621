// SPDX-License-Identifier: MIT
#pragma once
// PIG fingering text format (plain text used by piano-fingering research): a header line that
// starts with "//", then one note per line, tab separated:
//   id  onset_s  offset_s  spelledPitch  onVelocity  offVelocity  channel  finger
// channel 0 = right hand, 1 = left hand; finger 1..5, negative for the left hand; "a_b" (or
// "a_b_c" ...) is a finger substitution (strike with a, then the others in turn); a velocity of -1
// is "not recorded".
//
// Reading builds a two-part score ("Right hand", "Left hand") at 120 BPM, 480 ticks per quarter,
// with Note::finger / finger_substitute / hand filled. Errors name the file and line.

#include <filesystem>
#include <string>
#include <string_view>

#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>

namespace tutti::music {

Result<Score> read_pig(std::string_view text, const std::string& source_name);
Result<Score> read_pig_file(const std::filesystem::path& path);

// Writes every note; the hand comes from Note::hand (else the part's name, else pitch >= 60 is
// right), an unknown finger is written as 0. A score read from PIG (Score::pig_rows) is written
// line for line as it was read — order, ids, times, spellings, velocities — with only the
// finger column from the notes.
std::string write_pig(const Score& score);
Status write_pig_file(const Score& score, const std::filesystem::path& path);

}  // namespace tutti::music
