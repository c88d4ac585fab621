// SPDX-License-Identifier: MIT
#pragma once
// The ensemble's body motion, planned once per scene (Horii 2018: sway, weight shifts, breathing,
// the lead's cue, per-player variation), then evaluated per frame as a pure function of t
// (evaluate_body_motion.hpp). Every player follows the beat of their own score's tempo map.
//
//  - Sway: the upper body leans side to side, amplitude 0.5..4 deg (sway_amount), one cycle per
//    2..8 beats (sway_period), starting sway_phase into it; the torso twists a little with it.
//    While the player is idle (before 2 s ahead of their first breath, 2 s after their last note)
//    it keeps 30 % of its size.
//  - Weight shifts: at the bar lines, every 8..1 bars (weight_shift_rate), the hips move to the
//    other foot (±1.2..2.2 cm) over one beat.
//  - Breathing: at every BreathEvent of the player's breath plan the chest leans back (up to
//    1.8..4.5 deg by breath_depth, times the event's depth) and the shoulders rise (up to 6..15
//    mm), rising from the event's preparation (or inhale) start to its end, released over the
//    following 0.35 s.
//  - The lead's cues, at entrance times E: automatically one, before the first entrance (the
//    earliest first note of any player); or exactly the editor's list (EnsembleOptions::cues_s).
//    Each is one beat b long (the lead's beat at E): the bell lifts from E - b to E - b/2, dips
//    to its lowest at E as the knees flex (up to 3 cm), and settles by E + b/2. Size 0.3..1 of
//    the full gesture (cue_strength: 0.14 rad of bell lift). Followers answer each with the same
//    shape at a third of their cue_strength, 60..140 ms late (reaction). Cues never overlap: one
//    that would start before the previous one has settled is dropped (the earlier cue wins;
//    EnsemblePlan::dropped_cues). Without a lead there are no cues.
//  - Expressions (expression.hpp): the editor's strain / relaxed spans per player.
//  - Head: nods with the sway at half its rate, 1..4 deg (head_motion).
// Players who breathe in the same rest move together (their breath plans share the rest's
// window) but not alike: depth, sway and phase are theirs.

#include <cstdint>
#include <optional>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/ensemble_variation/expression.hpp>
#include <tutti/ensemble_variation/variation_params.hpp>
#include <tutti/music/score.hpp>

namespace tutti::ensemble_variation {

struct WeightShift {
  double start_s = 0.0;
  double end_s = 0.0;
  float from_m = 0.0f;
  float to_m = 0.0f;
};

struct BreathMotion {
  double rise_start_s = 0.0;  // the breath's preparation start, or its inhale start
  double peak_s = 0.0;        // the inhale's end
  double release_end_s = 0.0;
  float size = 0.0f;  // event depth x (0.4 + 0.6 breath_depth)
};

struct CueMotion {
  double start_s = 0.0;  // E - b (+ reaction delay for a follower)
  double lift_s = 0.0;   // E - b/2: the bell at its highest
  double dip_s = 0.0;    // E: lowest bell, knees most flexed
  double end_s = 0.0;    // E + b/2
  float strength = 0.0f;
};

struct PerformerMotionPlan {
  VariationParams params;
  music::TempoMap tempo;
  float sway_amplitude_rad = 0.0f;
  double sway_period_beats = 4.0;
  float head_amplitude_rad = 0.0f;
  double active_start_s = 0.0;
  double active_end_s = 0.0;
  float initial_shift_m = 0.0f;
  std::vector<WeightShift> weight_shifts;   // in time order, not overlapping
  std::vector<BreathMotion> breaths;        // in time order
  std::vector<CueMotion> cues;              // the lead's cues, or a follower's answers; in time
                                            // order, [start_s, end_s] not overlapping
  std::vector<ExpressionSpan> expressions;  // by start_s, not overlapping, amount in [0, 1]
};

// A breath the player takes, from their family's breath plan (a wind player's, a singer's): the
// chest rises with it, and a phrase breath also moves the weight.
struct BreathInput {
  double prepare_start_s = 0.0;  // the preparation starts (<= start_s)
  double start_s = 0.0;          // inhaling from start_s to end_s
  double end_s = 0.0;
  double depth = 1.0;  // 0..1, how full the lungs get
  // Taken where a phrase ends (in a rest); false for a catch-breath within a phrase or the breath
  // before the first entrance, which move no weight.
  bool phrase = true;
};

struct PerformerInput {
  std::uint64_t seed = 0;
  VariationParams params;
  bool lead = false;
  const music::Score* score = nullptr;  // the player's score (tempo map, time signatures)
  std::vector<BreathInput> breaths;  // in time order
  double first_onset_s = 0.0;  // first note the player plays
  double last_offset_s = 0.0;
  // The editor's expression spans, any order. Spans with end_s <= start_s or non-finite times
  // are dropped, amount is clamped to [0, 1]; where spans overlap, the later-starting one begins
  // when the earlier ends (and is dropped if nothing is left).
  std::vector<ExpressionSpan> expressions;
};

struct EnsembleOptions {
  // nullopt: automatic, one cue before the first entrance. Else exactly these entrance times E
  // (seconds, any order; an empty list = no cue; non-finite times are dropped).
  std::optional<std::vector<double>> cues_s;
};

struct EnsemblePlan {
  std::vector<PerformerMotionPlan> performers;  // in the order of the inputs
  int lead = -1;                                // index of the lead, -1 = none
  double entrance_s = 0.0;                      // the first entrance of anyone
  std::vector<double> cue_entrances_s;  // the E of every cue given, in time order (none without
                                        // a lead)
  int dropped_cues = 0;  // requested cues dropped: too close to the previous one, or not finite
};

// Deterministic: the same inputs give the same plan. Inputs without a score are an error.
Result<EnsemblePlan> plan_ensemble(const std::vector<PerformerInput>& performers,
                                   const EnsembleOptions& options = {});

}  // namespace tutti::ensemble_variation
