// SPDX-License-Identifier: MIT
#pragma once
// Makes the fingering planner's corridors acceptable to spline_motion::plan_hand_path without
// failing the run. The planner may ask for the impossible in two ways this file repairs:
//
//  1. A jump (legato hand shift): corridor i ends exactly when corridor i+1 starts and their
//     ranges do not overlap, so the hand would have to teleport. Repair: open a transition gap
//     by trimming the end of corridor i and the start of corridor i+1, each by
//     min(max_trim_s, max_trim_fraction x its own duration). The hand then moves during the last
//     moments of the release and the first moments of the attack. Durations are the corridors'
//     original ones, so a corridor trimmed at both ends keeps at least 1 - 2 x fraction of its
//     length; a zero-length corridor stays zero-length (valid) and is not trimmed.
//     These are real "the hand had to jump" moments: counted in `jumps`.
//  2. Contract violations (non-finite numbers, start > end, lo > hi, overlap in time, unsorted):
//     fixed in the least surprising way (drop non-finite, swap reversed pairs, sort, cut an
//     earlier corridor's end back to the next start) and counted in `sanitized` / `dropped`.
//
// A jump trimming cannot open (two zero-length corridors at one instant, or a zero-length
// corridor whose two touching neighbours are disjoint from each other) drops the later corridor
// of the conflict (counted in `dropped`), so the result always passes corridor_portals.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <tutti/piano_model/hand_corridor.hpp>

namespace tutti::piano_performance {

struct RepairOptions {
  double max_trim_s = 0.030;        // at most 30 ms taken from each side of a jump
  double max_trim_fraction = 0.25;  // and at most a quarter of each corridor's duration
};

struct CorridorRepair {
  piano_model::HandCorridors corridors;  // what the path is planned through
  std::vector<std::size_t> origin;  // per repaired corridor: its index in the input
  int jumps = 0;                    // transition gaps opened (kind 1)
  int sanitized = 0;                // corridors edited for a contract violation (kind 2)
  int dropped = 0;                  // corridors removed (non-finite, or an unopenable jump)
  std::vector<std::string> notes;   // one line per repair, for logs ("jump at 3.250 s ...")

  int total() const { return jumps + sanitized + dropped; }
};

CorridorRepair repair_corridors(std::span<const piano_model::HandCorridor> corridors,
                                const RepairOptions& options = {});

}  // namespace tutti::piano_performance
