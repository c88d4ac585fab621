// SPDX-License-Identifier: MIT
#pragma once
// The instrument and embouchure of one brass player at time t: a pure, allocation-free function
// of the plan and t (binary searches; same t → same pose; seek anywhere).

#include <array>

#include <tutti/brass_motion/brass_motion_plan.hpp>

namespace tutti::brass_motion {

// The brass model's names used here (systems/brass_model).
using brass_model::kMaxValves;

struct BrassPose {
  std::array<float, kMaxValves> valve_press{};  // 0 = up .. 1 = down
  double slide_mm = 0.0;
  double slide_position = 1.0;
  double slide_speed_mm_per_s = 0.0;
  double tension = 0.0;
  double corner_pull = 0.0;
  bool buzzing = false;  // a note sounds
};

BrassPose evaluate_brass_pose(const BrassMotionPlan& plan, double t);

// The easing every motion uses: 0 → 1 over u in [0, 1], zero velocity and acceleration at both
// ends (minimum jerk: 10u³ − 15u⁴ + 6u⁵); derivative with respect to u in `slope`.
double min_jerk(double u, double* slope = nullptr);

}  // namespace tutti::brass_motion
