// SPDX-License-Identifier: MIT
#pragma once
// A score's brass parts as players' lines. A part may hold several players ("2 Horns in E",
// chords in a trumpet staff): voice 0 is the top note of every chord, voice 1 the next one down
// (a player with no note of their own in a chord doubles the lowest: "a 2"). When the file numbers
// its voices (MusicXML <voice>), those are the players instead. A line is monophonic: a note still
// sounding when the next starts is cut there.

#include <span>
#include <vector>

#include <tutti/brass_model/brass_line.hpp>
#include <tutti/brass_model/instrument.hpp>
#include <tutti/core/result.hpp>
#include <tutti/music/score.hpp>

namespace tutti::fingering_planner {

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::Instrument;

struct BrassPart {
  int part = -1;  // Score part index
  const Instrument* instrument = nullptr;
  int voices = 1;  // players the part needs (most notes at once, or stated voices)
};

// Parts of `score` that `detect_instrument` recognises among `known`, in part order.
std::vector<BrassPart> find_brass_parts(const music::Score& score,
                                        std::span<const Instrument> known);

// Voices a part needs: stated voices when the file has several, else the most simultaneous notes.
int voices_in_part(const music::Score& score, int part);

// One player's line of `part`, played on `instrument`. Notes keep sounding pitch and get the
// written pitch; fingerings are not chosen yet (see brass_planner.hpp). Errors: no such part or
// voice.
Result<BrassLine> extract_line(const music::Score& score, int part, int voice,
                               const Instrument& instrument);

}  // namespace tutti::fingering_planner
