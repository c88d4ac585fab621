// SPDX-License-Identifier: MIT
#pragma once
// What a tool that edits a scene (the editor's timeline and inspector) shows of one player beyond
// what every player has (notes, planned breaths, variation and seed): filled by the player's
// family (FamilyPlugin::describe_player), so the editor draws any family's players without
// knowing them.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <tutti/scene/scene.hpp>

namespace tutti::stage {

// One of the player's notes as the family marks it: the note (score, index into its notes),
// the finger and hand, or the foot, that play it, and whether the user pinned its finger.
struct NoteMarking {
  std::size_t score = 0;
  std::size_t note = 0;
  int finger = 0;  // 1..5 as planned; 0 = none
  bool right_hand = true;
  int foot = -1;  // 0 right, 1 left; -1 = played by the hands
  bool pinned = false;
};

// Where a hand may be for one event (a band, keyboard x in mm) over [start_s, end_s].
struct HandBand {
  double start_s = 0.0, end_s = 0.0, lo_mm = 0.0, hi_mm = 0.0;
};

// A note the user pinned to a finger (the player's "pins" in the scene file).
struct PinView {
  double time_s = 0.0;
  int key = 60;
  int finger = 1;
};

struct PlayerView {
  // The name a lane shows, when not the player's own (empty: components::Performer::name).
  std::string lane_name;
  // A line under the player's name: their instrument and part, hand size, ...
  std::string summary;
  // The variation as the scene file gives it (the seed is components::Performer's).
  scene::Variation variation;
  // Notes played by fingers: each may be pinned to a finger (pins, the scene file's "pins").
  bool fingered = false;
  std::vector<PinView> pins;
  std::vector<NoteMarking> notes;  // sorted by (score, note): looked up by binary search
  // Takes expression spans (the scene file's "expressions"), as written.
  bool expressive = false;
  std::vector<scene::Expression> expressions;
  // A fingered player's hands: the allowed bands per event and the planned path through them,
  // sampled every kHandPathStep_s as (time, keyboard x mm); right, then left.
  std::array<std::vector<HandBand>, 2> hand_bands;
  std::array<std::vector<std::array<double, 2>>, 2> hand_path;
};

inline constexpr double kHandPathStep_s = 0.02;

}  // namespace tutti::stage
