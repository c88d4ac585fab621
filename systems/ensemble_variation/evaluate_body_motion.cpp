// SPDX-License-Identifier: MIT
#include <tutti/ensemble_variation/evaluate_body_motion.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tutti::ensemble_variation {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kIdleSway = 0.3;
constexpr double kIdleFade_s = 2.0;
constexpr double kCueBellLift_rad = 0.14;
constexpr double kCueKnees_m = 0.03;
constexpr double kLeanBack_rad = 0.0785;  // 4.5 deg at a full-size breath
constexpr double kShoulderLift_m = 0.015;
// Expressions at full amount. Strain: shoulders pulled up 12 mm, the breathing chest's lean
// halved, 60 % less sway, the bell 0.05 rad (3 deg) higher. Relaxed: shoulders 10 mm lower,
// 60 % more sway and head motion, the shown strain gone.
constexpr double kStrainShoulders_m = 0.012;
constexpr double kStrainChest = 0.5;
constexpr double kStrainSway = 0.6;
constexpr double kStrainBell_rad = 0.05;
constexpr double kRelaxedShoulders_m = 0.010;
constexpr double kRelaxedSway = 0.6;

// Minimum-jerk ease from 0 at a to 1 at b.
double ease(double t, double a, double b) {
  if (t <= a) return 0.0;
  if (t >= b) return 1.0;
  const double u = (t - a) / (b - a);
  return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

double activity(const PerformerMotionPlan& plan, double t) {
  const double in = ease(t, plan.active_start_s - kIdleFade_s, plan.active_start_s);
  const double out = 1.0 - ease(t, plan.active_end_s, plan.active_end_s + kIdleFade_s);
  return kIdleSway + (1.0 - kIdleSway) * std::min(in, out);
}

double weight_shift(const PerformerMotionPlan& plan, double t) {
  const auto& shifts = plan.weight_shifts;
  // The last shift that started at or before t.
  auto it = std::upper_bound(shifts.begin(), shifts.end(), t,
                             [](double time, const WeightShift& s) { return time < s.start_s; });
  if (it == shifts.begin()) return plan.initial_shift_m;
  const WeightShift& s = *(it - 1);
  return s.from_m + (s.to_m - s.from_m) * ease(t, s.start_s, s.end_s);
}

}  // namespace

double breath_envelope(const PerformerMotionPlan& plan, double t) {
  const auto& breaths = plan.breaths;
  auto it =
      std::upper_bound(breaths.begin(), breaths.end(), t,
                       [](double time, const BreathMotion& b) { return time < b.rise_start_s; });
  if (it == breaths.begin()) return 0.0;
  const BreathMotion& b = *(it - 1);
  if (t >= b.release_end_s) return 0.0;
  const double level =
      t <= b.peak_s ? ease(t, b.rise_start_s, b.peak_s) : 1.0 - ease(t, b.peak_s, b.release_end_s);
  return level * b.size;
}

double cue_lift(const CueMotion& cue, double t) {
  if (t <= cue.start_s || t >= cue.end_s) return 0.0;
  if (t <= cue.lift_s) return ease(t, cue.start_s, cue.lift_s);
  if (t <= cue.dip_s) return 1.0 - 1.4 * ease(t, cue.lift_s, cue.dip_s);
  return -0.4 * (1.0 - ease(t, cue.dip_s, cue.end_s));
}

double cue_knees(const CueMotion& cue, double t) {
  if (t <= cue.lift_s || t >= cue.end_s) return 0.0;
  if (t <= cue.dip_s) return ease(t, cue.lift_s, cue.dip_s);
  return 1.0 - ease(t, cue.dip_s, cue.end_s);
}

const CueMotion* cue_at(const PerformerMotionPlan& plan, double t) {
  const auto& cues = plan.cues;
  const auto it =
      std::upper_bound(cues.begin(), cues.end(), t,
                       [](double time, const CueMotion& c) { return time < c.start_s; });
  return it == cues.begin() ? nullptr : &*(it - 1);
}

ExpressionLevel expression_at(const PerformerMotionPlan& plan, double t) {
  ExpressionLevel level;
  const auto& spans = plan.expressions;
  const auto it =
      std::upper_bound(spans.begin(), spans.end(), t,
                       [](double time, const ExpressionSpan& s) { return time < s.start_s; });
  if (it == spans.begin()) return level;
  const ExpressionSpan& s = *(it - 1);
  if (!(t < s.end_s)) return level;
  // Ramps inside the span, so disjoint spans never blend and the edges are 0.
  const double ramp = std::min(kExpressionRamp_s, 0.5 * (s.end_s - s.start_s));
  const double weight = s.amount * std::min(ease(t, s.start_s, s.start_s + ramp),
                                            1.0 - ease(t, s.end_s - ramp, s.end_s));
  (s.kind == ExpressionKind::strain ? level.strain : level.relaxed) = weight;
  return level;
}

components::BodyMotion evaluate_body_motion(const PerformerMotionPlan& plan, double t,
                                            double breath_strain) {
  components::BodyMotion m;
  m.strain = std::clamp(breath_strain, 0.0, 1.0);
  if (!std::isfinite(t)) return m;
  const double beats = plan.tempo.beats_at_seconds(t);
  const double cycle = kTwoPi * (beats / plan.sway_period_beats + plan.params.sway_phase);
  const double a = activity(plan, t);
  m.sway_rad = static_cast<float>(a * plan.sway_amplitude_rad * std::sin(cycle));
  m.twist_rad = static_cast<float>(0.4 * a * plan.sway_amplitude_rad * std::cos(cycle));
  m.head_nod_rad = static_cast<float>(
      a * plan.head_amplitude_rad *
      std::sin(0.5 * kTwoPi * (beats / plan.sway_period_beats) + kTwoPi * plan.params.sway_phase));
  m.hips_shift_m = static_cast<float>(weight_shift(plan, t));
  const double breath = breath_envelope(plan, t);
  m.lean_back_rad = static_cast<float>(breath * kLeanBack_rad);
  m.shoulder_lift_m = static_cast<float>(breath * kShoulderLift_m);
  if (const CueMotion* cue = cue_at(plan, t)) {
    m.bell_lift_rad = static_cast<float>(cue->strength * kCueBellLift_rad * cue_lift(*cue, t));
    m.knee_flex_m = static_cast<float>(cue->strength * kCueKnees_m * cue_knees(*cue, t));
  }
  // Only inside a span, so everything outside stays bit for bit as without expressions.
  const ExpressionLevel expression = expression_at(plan, t);
  if (expression.strain > 0.0) {
    const double s = expression.strain;
    m.sway_rad = static_cast<float>(m.sway_rad * (1.0 - kStrainSway * s));
    m.twist_rad = static_cast<float>(m.twist_rad * (1.0 - kStrainSway * s));
    m.lean_back_rad = static_cast<float>(m.lean_back_rad * (1.0 - kStrainChest * s));
    m.shoulder_lift_m = static_cast<float>(m.shoulder_lift_m + kStrainShoulders_m * s);
    m.bell_lift_rad = static_cast<float>(m.bell_lift_rad + kStrainBell_rad * s);
    m.strain = std::max(m.strain, s);
  } else if (expression.relaxed > 0.0) {
    const double r = expression.relaxed;
    m.sway_rad = static_cast<float>(m.sway_rad * (1.0 + kRelaxedSway * r));
    m.twist_rad = static_cast<float>(m.twist_rad * (1.0 + kRelaxedSway * r));
    m.head_nod_rad = static_cast<float>(m.head_nod_rad * (1.0 + kRelaxedSway * r));
    m.shoulder_lift_m = static_cast<float>(m.shoulder_lift_m - kRelaxedShoulders_m * r);
    m.strain *= 1.0 - r;
  }
  return m;
}

}  // namespace tutti::ensemble_variation
