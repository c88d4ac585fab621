// SPDX-License-Identifier: MIT
#include <tutti/fingering_planner/live_hand_split.hpp>

#include <algorithm>
#include <cmath>

namespace tutti::fingering_planner {

// The piano model's names this planner uses (systems/piano_model).
using piano_model::Keyboard;

LiveHandSplit::LiveHandSplit(const FingeringModel& model)
    : model_(&model),
      reach_mm_(model.hand.reach_mm()) {}

bool LiveHandSplit::can_take(music::Hand side, int key) const {
  const Keyboard& keyboard = model_->keyboard;
  auto x_of = [&](int k) {
    return keyboard.x_mm(std::clamp(k, keyboard.lowest_key(), keyboard.highest_key()));
  };
  const auto& mine = down_[index(side)];
  const auto& other =
      down_[index(side == music::Hand::left ? music::Hand::right : music::Hand::left)];
  if (mine.size() >= 5) return false;
  for (const Down& d : mine) {
    if (std::abs(x_of(d.key) - x_of(key)) > reach_mm_) return false;
  }
  for (const Down& d : other) {
    if (side == music::Hand::right ? key < d.key : key > d.key) return false;
  }
  return true;
}

music::Hand LiveHandSplit::assign(std::int64_t id, int key) {
  const bool right_ok = can_take(music::Hand::right, key);
  const bool left_ok = can_take(music::Hand::left, key);
  const music::Hand by_middle_c = key >= 60 ? music::Hand::right : music::Hand::left;
  music::Hand side = by_middle_c;
  if (right_ok && !left_ok) {
    side = music::Hand::right;
  } else if (left_ok && !right_ok) {
    side = music::Hand::left;
  } else if (right_ok && left_ok) {
    const double to_right = std::abs(key - last_key_[0]);
    const double to_left = std::abs(key - last_key_[1]);
    if (to_right != to_left) side = to_right < to_left ? music::Hand::right : music::Hand::left;
  }
  hold(id, key, side);
  return side;
}

void LiveHandSplit::hold(std::int64_t id, int key, music::Hand side) {
  down_[index(side)].push_back({id, key});
  last_key_[index(side)] = key;
}

void LiveHandSplit::release(std::int64_t id) {
  for (auto& hand : down_) {
    std::erase_if(hand, [&](const Down& d) { return d.id == id; });
  }
}

}  // namespace tutti::fingering_planner
