// SPDX-License-Identifier: MIT
#include <tutti/finger_motion/plan_pass_over.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace tutti::finger_motion {
namespace {

struct Span {
  double from_s = 0.0;
  double to_s = 0.0;
};

// The hand's need to be over the other one: [from, to] while the hands overlap.
struct Need {
  std::size_t side = 0;  // 0 right, 1 left
  Span span;
};

// How far a hand travels over [from, to] (mm, along its path).
double travel_mm(const spline_motion::HandPath& path, double from_s, double to_s, double step_s) {
  double length = 0.0;
  double x = spline_motion::evaluate(path, from_s).x_mm;
  for (double t = from_s + step_s; t < to_s + 0.5 * step_s; t += step_s) {
    const double next = spline_motion::evaluate(path, t).x_mm;
    length += std::abs(next - x);
    x = next;
  }
  return length;
}

// Spans where the hands' reference points are closer than gap_mm on their own sides or crossed
// by less than crossed_mm. The hand over the other is the one that crosses it: of the two, the
// one that travels further from an ease before the span to an ease after it (the right one when
// neither moves).
std::vector<Need> needs_from_paths(const spline_motion::HandPath& right_path,
                                   const spline_motion::HandPath& left_path, double from_s, double to_s,
                                   const PassOverParams& params) {
  std::vector<Need> needs;
  const auto steps = static_cast<std::size_t>(std::ceil((to_s - from_s) / params.sample_s));
  bool inside = false;
  for (std::size_t i = 0; i <= steps; ++i) {
    const double t = from_s + static_cast<double>(i) * params.sample_s;
    const spline_motion::HandState right = spline_motion::evaluate(right_path, t);
    const spline_motion::HandState left = spline_motion::evaluate(left_path, t);
    // > 0: the right hand's reference point to the right of the left's, as the hands sit.
    const double gap = right.x_mm - left.x_mm;
    const bool overlap = gap < params.gap_mm && gap > -params.crossed_mm;
    if (overlap && inside) {
      needs.back().span.to_s = t;
    } else if (overlap) {
      needs.push_back({0, {t, t}});
    }
    inside = overlap;
  }
  for (Need& need : needs) {
    const double from = need.span.from_s - params.ease_s;
    const double to = need.span.to_s + params.ease_s;
    need.side = travel_mm(right_path, from, to, params.sample_s) >=
                        travel_mm(left_path, from, to, params.sample_s)
                    ? 0
                    : 1;
  }
  return needs;
}

}  // namespace

void plan_pass_over(FingerMotionPlan& plan, const spline_motion::HandPath& right_path,
                    const spline_motion::HandPath& left_path, const PassOverParams& params) {
  plan.right.pass_over.lifts.clear();
  plan.left.pass_over.lifts.clear();
  if (right_path.empty() || left_path.empty() || !(params.lift_mm > 0.0) ||
      !(params.sample_s > 0.0)) {
    return;
  }
  double from_s = std::numeric_limits<double>::infinity();
  double to_s = -from_s;
  std::array<bool, 2> plays{};
  for (const HandFingerPlan* hand : {&plan.right, &plan.left}) {
    for (const std::vector<KeyContact>& finger : hand->fingers) {
      if (finger.empty()) continue;
      plays[hand == &plan.left ? 1 : 0] = true;
      from_s = std::min(from_s, finger.front().shape_start_s);
      to_s = std::max(to_s, finger.back().release_end_s);
    }
  }
  // Both hands play: otherwise there is nothing to pass over.
  if (!plays[0] || !plays[1]) return;
  {
    // The middle finger on a white key's bottom, from the hand at its height and lifted.
    const FingerGeometry& g = plan.geometry[2];
    const double drop = g.root_z_mm - (plan.keys.white_top_z_mm - plan.keys.dip_mm + g.pad_drop_mm);
    const ChainShape& white = plan.white_shape[2];
    const double reach = solve_stroke(white, drop).reach_y_mm;
    const double lifted_drop = drop + params.lift_mm;
    const double lifted = solve_stroke(reaching_shape(g, white, lifted_drop), lifted_drop).reach_y_mm;
    const double in_per_lift = std::max(0.0, reach - lifted) / params.lift_mm;
    plan.right.pass_over.in_per_lift = in_per_lift;
    plan.left.pass_over.in_per_lift = in_per_lift;
  }
  for (const Need& need : needs_from_paths(right_path, left_path, from_s, to_s, params)) {
    PassOverLift lift;
    lift.top_from_s = need.span.from_s;
    lift.top_to_s = need.span.to_s;
    lift.rise_from_s = lift.top_from_s - params.ease_s;
    lift.down_to_s = lift.top_to_s + params.ease_s;
    lift.height_mm = params.lift_mm;
    std::vector<PassOverLift>& lifts = (need.side == 0 ? plan.right : plan.left).pass_over.lifts;
    // Lifts whose eases meet are one.
    if (!lifts.empty() && lift.rise_from_s < lifts.back().down_to_s) {
      lifts.back().top_to_s = lift.top_to_s;
      lifts.back().down_to_s = lift.down_to_s;
      continue;
    }
    lifts.push_back(lift);
  }
}

}  // namespace tutti::finger_motion
