// SPDX-License-Identifier: MIT
#pragma once
// A hand path for live notes: the hand holds still, and when a hand's keys change it moves to
// its new place with a quintic that starts from the hand's current position, velocity and
// acceleration (a move may cut into the one before) and arrives at rest after `move_s`. The
// fingertips reach their keys at once (the spread takes up the difference), so the hand's lag
// does not delay a key. Rolling: only the last moves are kept.

#include <cstddef>
#include <deque>

#include <tutti/spline_motion/hand_path.hpp>

namespace tutti::live {

class LiveHandPath {
 public:
  explicit LiveHandPath(double start_x_mm, double move_s = 0.08, std::size_t kept_moves = 16);

  // From t_s on, go to x_mm. t_s >= the last move's start; a move at the same start replaces it.
  void move_to(double t_s, double x_mm);
  spline_motion::HandState state(double t_s) const;  // of the moves so far
  spline_motion::HandPath build() const;             // the same as a HandPath

 private:
  struct Move {
    double start_s = 0.0;
    double duration_s = 0.0;
    double to_x_mm = 0.0;
    spline_motion::Poly5 poly;
  };
  double move_s_;
  std::size_t kept_;
  std::deque<Move> moves_;
};

}  // namespace tutti::live
