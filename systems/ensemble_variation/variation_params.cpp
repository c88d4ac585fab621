// SPDX-License-Identifier: MIT
#include <tutti/ensemble_variation/variation_params.hpp>

#include <tutti/core/splitmix64.hpp>

namespace tutti::ensemble_variation {

double unit_from_seed(std::uint64_t seed, std::uint64_t stream) {
  const std::uint64_t bits = splitmix64(splitmix64(seed) ^ (stream * 0xD1B54A32D192ED03ull));
  return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

VariationParams draw_variation(std::uint64_t seed) {
  VariationParams p;
  p.sway_amount = unit_from_seed(seed, 1);
  p.sway_period = unit_from_seed(seed, 2);
  p.sway_phase = unit_from_seed(seed, 3);
  p.weight_shift_rate = unit_from_seed(seed, 4);
  p.breath_depth = unit_from_seed(seed, 5);
  p.cue_strength = unit_from_seed(seed, 6);
  p.head_motion = unit_from_seed(seed, 7);
  p.reaction = unit_from_seed(seed, 8);
  return p;
}

VariationParams resolve_variation(std::uint64_t seed, const VariationOverrides& overrides) {
  VariationParams p = draw_variation(seed);
  const auto take = [](double& field, const std::optional<double>& given) {
    if (given) field = *given;
  };
  take(p.sway_amount, overrides.sway_amount);
  take(p.sway_period, overrides.sway_period);
  take(p.sway_phase, overrides.sway_phase);
  take(p.weight_shift_rate, overrides.weight_shift_rate);
  take(p.breath_depth, overrides.breath_depth);
  take(p.cue_strength, overrides.cue_strength);
  take(p.head_motion, overrides.head_motion);
  return p;
}

}  // namespace tutti::ensemble_variation
