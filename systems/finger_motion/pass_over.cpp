// SPDX-License-Identifier: MIT
#include <tutti/finger_motion/pass_over.hpp>

#include <algorithm>

#include <tutti/finger_motion/finger_chain.hpp>

namespace tutti::finger_motion {

double evaluate_pass_over(const PassOver& pass_over, double t_s) noexcept {
  // The first lift not yet over at t (NaN compares false: "before everything").
  const auto lift = std::upper_bound(
      pass_over.lifts.begin(), pass_over.lifts.end(), t_s,
      [](double t, const PassOverLift& l) { return t < l.down_to_s; });
  if (lift == pass_over.lifts.end() || !(t_s > lift->rise_from_s)) return 0.0;
  if (t_s < lift->top_from_s) {
    return lift->height_mm *
           min_jerk((t_s - lift->rise_from_s) / (lift->top_from_s - lift->rise_from_s));
  }
  if (t_s <= lift->top_to_s) return lift->height_mm;
  return lift->height_mm *
         min_jerk((lift->down_to_s - t_s) / (lift->down_to_s - lift->top_to_s));
}

}  // namespace tutti::finger_motion
