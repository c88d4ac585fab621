// SPDX-License-Identifier: MIT
#pragma once
// The editor's expressions (issue 7): a span of time in which a player is shown working hard
// (strain) or at ease (relaxed), on top of the planned motion. plan_ensemble cleans the spans
// (PerformerMotionPlan::expressions); evaluate_body_motion applies them (README.md in this
// folder):
//  - strain:  shoulders up and the breathing chest tighter, less sway, the bell a little higher,
//             and the shown strain (BodyMotion::strain) at least `amount`;
//  - relaxed: shoulders down, a wider sway (same period, so it reads slower and broader), the
//             shown strain scaled by 1 - amount.
// Each span fades in over its first and out over its last kExpressionRamp_s (less when the span
// is shorter than two ramps), so the motion is continuous in t; outside every span the motion is
// bit for bit what it is without expressions.

namespace tutti::ensemble_variation {

enum class ExpressionKind { strain, relaxed };

struct ExpressionSpan {
  ExpressionKind kind = ExpressionKind::strain;
  double start_s = 0.0;
  double end_s = 0.0;
  double amount = 1.0;  // 0..1
};

inline constexpr double kExpressionRamp_s = 0.3;

}  // namespace tutti::ensemble_variation
