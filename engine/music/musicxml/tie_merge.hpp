// SPDX-License-Identifier: MIT
#pragma once
// Tied notes become one sounding note: a chain start -> (continue ->)* stop keeps the first
// note's identity (source_index, finger, velocity) and takes the last note's offset.
//
// Matching works on sounding order (onset, then document order) so voices interleaved by
// <backup> cannot break a chain: a stop joins the open tie of the same pitch in the same voice,
// else of the same pitch in any voice of the part. A new attack of a pitch drops a dangling tie
// of that pitch and voice; a stop with nothing open stays a note of its own.

#include <vector>

#include <tutti/music/score.hpp>

namespace tutti::music::musicxml {

struct TieMarkedNote {
  Note note;
  bool tie_start = false;
  bool tie_stop = false;
};

// The notes of one part with every tie chain merged, sorted by onset (stable).
std::vector<Note> merge_ties(std::vector<TieMarkedNote> notes);

}  // namespace tutti::music::musicxml
