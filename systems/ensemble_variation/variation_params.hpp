// SPDX-License-Identifier: MIT
#pragma once
// A performer's variation parameters, each in [0, 1]: drawn from the performer's seed (each
// field its own splitmix64 stream, so adding a field later leaves the others as they were), then
// overridden field by field by what the scene gives (VariationOverrides, a scene's "variation").

#include <cstdint>
#include <optional>

namespace tutti::ensemble_variation {

// Per-performer expression controls, each normalised to [0, 1]; the ensemble-variation system
// maps them onto the ranges its style data gives. Absent (nullopt) = drawn from the performer's
// seed (draw_variation). The scene file's keys: scene::kVariationFields.
struct VariationOverrides {
  std::optional<double> sway_amount;        // 0 = still, 1 = the style's widest body sway
  std::optional<double> sway_period;        // 0 = the shortest sway period, 1 = the longest
  std::optional<double> sway_phase;         // where in its cycle the sway starts (fraction)
  std::optional<double> weight_shift_rate;  // how often weight moves between the feet
  std::optional<double> breath_depth;       // how visibly the chest and shoulders breathe
  std::optional<double> cue_strength;       // size of the lead's cue gesture / the followers' reply
  std::optional<double> head_motion;        // how much the head follows the phrase
  friend bool operator==(const VariationOverrides&, const VariationOverrides&) = default;
};

struct VariationParams {
  double sway_amount = 0.5;
  double sway_period = 0.5;
  double sway_phase = 0.0;
  double weight_shift_rate = 0.5;
  double breath_depth = 0.5;
  double cue_strength = 0.5;
  double head_motion = 0.5;
  // Not in the scene: how late a follower answers the lead's cue, [0, 1] -> 60..140 ms.
  double reaction = 0.5;
  friend bool operator==(const VariationParams&, const VariationParams&) = default;
};

// A uniform number in [0, 1) from (seed, stream): splitmix64.
double unit_from_seed(std::uint64_t seed, std::uint64_t stream);

VariationParams draw_variation(std::uint64_t seed);
VariationParams resolve_variation(std::uint64_t seed, const VariationOverrides& overrides);

}  // namespace tutti::ensemble_variation
