// SPDX-License-Identifier: MIT
#pragma once
// Which hand plays a note that arrives live, decided at arrival (no lookahead, no undo): the
// hand whose last struck key is nearest, unless that hand cannot take it — it already holds
// five keys, the key is beyond its reach from the keys it holds (thumb's lowest to little
// finger's highest), or taking it would cross the other hand's held keys (the right hand never
// plays below a key the left holds, nor the left above one the right holds). Ties, and a note
// neither hand can take cleanly, go by middle C (right from C4 up). The hands start around G4
// and C3, as hand_assignment.hpp's automatic split does. Deterministic.

#include <array>
#include <cstdint>
#include <vector>

#include <tutti/fingering_planner/fingering_model.hpp>
#include <tutti/music/score.hpp>

namespace tutti::fingering_planner {

class LiveHandSplit {
 public:
  explicit LiveHandSplit(const FingeringModel& model);  // model must outlive the split

  // A note starts: its hand (left or right). Keys off the keyboard are clamped for reach.
  music::Hand assign(std::int64_t id, int key);
  // A note the caller gave to `side` (left or right) starts: tracked like an assigned one.
  void hold(std::int64_t id, int key, music::Hand side);
  // It ended (unknown ids are ignored).
  void release(std::int64_t id);

  // Keys a hand holds now (for tests).
  std::size_t held(music::Hand side) const { return down_[index(side)].size(); }

 private:
  struct Down {
    std::int64_t id = 0;
    int key = 60;
  };
  static std::size_t index(music::Hand side) { return side == music::Hand::left ? 1 : 0; }
  bool can_take(music::Hand side, int key) const;

  const FingeringModel* model_;
  double reach_mm_ = 0.0;
  std::array<double, 2> last_key_{67.0, 48.0};  // right, left
  std::array<std::vector<Down>, 2> down_;
};

}  // namespace tutti::fingering_planner
