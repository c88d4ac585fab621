// SPDX-License-Identifier: MIT
#pragma once
// The planned motion of one brass player's instrument and embouchure: immutable data, built once
// from a fingered line (plan_brass_motion.hpp), evaluated at any t (evaluate_brass_pose.hpp).

#include <array>
#include <vector>

#include <tutti/brass_model/instrument.hpp>
#include <tutti/spline_motion/plateau_envelope.hpp>

namespace tutti::brass_motion {

// The brass model's names used here (systems/brass_model).
using brass_model::kMaxValves;

// One press of one valve: down from press_s to down_s, held, up from release_s to up_s.
struct ValveStroke {
  double press_s = 0.0;
  double down_s = 0.0;
  double release_s = 0.0;
  double up_s = 0.0;
};

// The slide moving from one extension to another (minimum-jerk: no velocity or acceleration
// jumps; peak speed 1.875 × distance / duration). Between moves it stays put.
struct SlideMove {
  double start_s = 0.0;
  double end_s = 0.0;
  float from_mm = 0.0f;
  float to_mm = 0.0f;
  float from_position = 1.0f;
  float to_position = 1.0f;
};

// Embouchure tension easing from one value to another over [start_s, end_s]; constant between.
struct TensionRamp {
  double start_s = 0.0;
  double end_s = 0.0;
  float from = 0.0f;
  float to = 0.0f;
};

struct SoundingSpan {
  double onset_s = 0.0;
  double offset_s = 0.0;
};

struct BrassMotionPlan {
  int valve_count = 0;
  std::array<std::vector<ValveStroke>, kMaxValves> valves;  // per valve, in time order
  bool has_slide = false;
  float slide_start_mm = 0.0f;  // before the first move
  float slide_start_position = 1.0f;
  std::vector<SlideMove> slide;      // in time order, not overlapping
  // The slide's extension (mm) the body is set for at each moment: never less than the slide's
  // own, eased (plan_brass_motion.cpp, plan_slide_reach).
  tutti::spline_motion::PlateauEnvelope slide_reach;
  float rest_tension = 0.0f;         // before the first ramp
  std::vector<TensionRamp> tension;  // in time order, not overlapping
  float corner_pull_from = 0.45f;
  std::vector<SoundingSpan> sounding;  // playable notes, in time order
  int late_slide_moves = 0;            // moves that could not arrive by their onset
};

}  // namespace tutti::brass_motion
