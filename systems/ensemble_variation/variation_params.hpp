#pragma once
// A performer's variation parameters, each in [0, 1]: drawn from the performer's seed (each
// field its own splitmix64 stream, so adding a field later leaves the others as they were), then
// overridden field by field by what the scene gives (scene::Variation).

#include <cstdint>

#include "scene/scene.hpp"

namespace tutti::ensemble {

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
VariationParams resolve_variation(std::uint64_t seed, const scene::Variation& overrides);

}  // namespace tutti::ensemble
