// SPDX-License-Identifier: MIT
#pragma once
// An organist's feet on the pedalboard: which notes they play, which foot plays each, and where
// each foot is at time t. Planned once (plan_feet); evaluate_foot(plan, foot, t) is a pure, cheap
// function of the plan and t, so any frame can be posed alone.
//
// The feet play the lowest line: a part named as the pedals' ("Pedal", "Pédale"), else the third
// staff of a three-staff part (organ scores write the pedals there), else the lowest of several
// parts when it is a single line in the pedals' register (a chorale's bass, a continuo), else,
// at each onset, the lowest note when it lies below the board's split. Each foot plays the notes on its side of the
// board unless the other foot is nearer and free; a held note keeps its foot, so two overlapping
// pedal notes are played one by each foot.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <tutti/music/score.hpp>

namespace tutti::piano_model {
struct Pedalboard;
}

namespace tutti::piano {

inline constexpr int kRightFoot = 0;
inline constexpr int kLeftFoot = 1;

struct PedalPress {
  int key = 36;           // the pedal (MIDI key, on the board)
  double down_s = 0.0;    // the pedal reaches the bottom: the note sounds
  double up_s = 0.0;      // the pedal starts up: the note stops (>= down_s)
  int foot = kRightFoot;
  std::size_t note = 0;   // the note's index in the score planned
  double x_m = 0.0;       // across the board (piano_model/pedal_geometry.hpp)
};

struct FeetPlan {
  std::vector<PedalPress> presses;                    // by down_s
  std::array<std::vector<std::uint32_t>, 2> by_foot;  // each foot's presses, in time order
  std::array<int, 2> rest_key{-1, -1};                // where each foot waits before it plays
  std::array<double, 2> rest_x_m{0.0, 0.0};
  std::size_t folded = 0;  // notes moved by octaves onto the board's keys
  bool empty() const { return presses.empty(); }
};

// Which of `score`'s notes the feet play (see the header's comment), by index.
std::vector<bool> choose_pedal_notes(const music::Score& score,
                                     const piano_model::Pedalboard& board);

// The marked notes on the board's keys (folded by octaves), each given a foot.
FeetPlan plan_feet(const music::Score& score, const std::vector<bool>& pedal_notes,
                   const piano_model::Pedalboard& board);

// A foot at one moment: over pedal `from_key`, moving toward `to_key` (the same when still),
// pressing `from_key` by `depth` (0 up .. 1 down), the sole `lift_m` above the pedal's top.
struct FootState {
  int from_key = -1;  // -1: the foot has nothing to play
  int to_key = -1;
  double travel = 0.0;  // 0 at from_key .. 1 at to_key, eased
  double depth = 0.0;
  double lift_m = 0.0;
};

// How a foot moves (seconds, metres): the pedal goes down in `press_s` before the note and up in
// `release_s` after it; a foot hovers `hover_m` above a pedal it is not pressing and lifts
// `step_lift_m` more midway through a move, which takes between `min_move_s` and `max_move_s`
// at `move_speed_m_s`.
struct FootTiming {
  static constexpr double press_s = 0.06;
  static constexpr double release_s = 0.06;
  static constexpr double hover_m = 0.012;
  static constexpr double step_lift_m = 0.02;
  static constexpr double min_move_s = 0.08;
  static constexpr double max_move_s = 0.35;
  static constexpr double move_speed_m_s = 1.2;
};

FootState evaluate_foot(const FeetPlan& plan, int foot, double t);

// Notes the feet play at once at most (one per foot).
inline constexpr int kFeet = 2;

}  // namespace tutti::piano
