// SPDX-License-Identifier: MIT
#pragma once
// Room for the other hand: a hand that is not playing moves out of the other hand's way.
//
// Between two of a hand's corridors (its keys let go, the next not yet struck) the taut string
// leaves the hand where it was, or drifts it straight toward its next keys; meanwhile the other
// hand may come to play right there (Mozart's K. 545 at 3.0 s: the right thumb comes down to C4
// while the idle left hand still hovers over E4), and the two hands pass through each other. A
// pianist moves the free hand aside. So each idle gap, from `leave_s` after the last release to
// `leave_s` before the next strike, gets corridors of `step_s` or less that keep this hand's
// thumb side (its reference point + `thumb_mm` toward the other hand) `clearance_mm` short of the
// other hand's thumb side: that hand's reference point + `thumb_mm` toward this one, or its
// outermost key there if it stretches further (HandCorridor::keys_lo_mm / keys_hi_mm). They
// bound one side only, so consecutive ones always overlap (no forced jump), and where the other
// hand is far they change nothing.

#include <span>

#include <tutti/music/score.hpp>
#include <tutti/piano_model/hand_corridor.hpp>
#include <tutti/spline_motion/hand_path.hpp>

namespace tutti::piano_performance {

struct IdleRoomOptions {
  double thumb_mm = 47.0;      // the resting thumb two white keys (23.5 mm) from the middle finger
  double clearance_mm = 23.5;  // one white key between the two thumbs
  double leave_s = 0.06;       // the hand stays this long after its release and before its strike
  double step_s = 0.1;         // the longest added corridor
};

// `corridors`: this hand's, sorted and well formed (as the fingering planner gives them; others
// are returned unchanged). `other_corridors` and `other`: the other hand's corridors and path
// (an empty path = nothing added). `side`: this hand.
piano_model::HandCorridors with_idle_room(
    std::span<const piano_model::HandCorridor> corridors,
    std::span<const piano_model::HandCorridor> other_corridors,
    const spline_motion::HandPath& other, music::Hand side, const IdleRoomOptions& options = {});

}  // namespace tutti::piano_performance
