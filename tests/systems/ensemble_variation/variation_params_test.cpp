// SPDX-License-Identifier: MIT
// Variation parameters from seeds (ensemble_variation/variation_params.hpp).
#include <tutti/ensemble_variation/variation_params.hpp>

#include <gtest/gtest.h>

namespace tutti::ensemble_variation {
namespace {

std::vector<double> fields(const VariationParams& p) {
  return {p.sway_amount,  p.sway_period,  p.sway_phase,  p.weight_shift_rate,
          p.breath_depth, p.cue_strength, p.head_motion, p.reaction};
}

TEST(VariationParams, SameSeedSameParametersAllInTheUnitInterval) {
  EXPECT_EQ(draw_variation(7), draw_variation(7));
  for (std::uint64_t seed : {0ull, 1ull, 7ull, 0xFFFFFFFFFFFFFFFFull}) {
    for (double f : fields(draw_variation(seed))) {
      EXPECT_GE(f, 0.0);
      EXPECT_LT(f, 1.0);
    }
  }
}

TEST(VariationParams, NeighbouringSeedsDifferInEveryField) {
  const std::vector<double> a = fields(draw_variation(7));
  const std::vector<double> b = fields(draw_variation(8));
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NE(a[i], b[i]) << i;
  // Over many seeds the draws spread over [0, 1): a mean near 1/2.
  double sum = 0.0;
  for (std::uint64_t seed = 0; seed < 2000; ++seed) sum += draw_variation(seed).sway_amount;
  EXPECT_NEAR(sum / 2000.0, 0.5, 0.03);
}

TEST(VariationParams, SceneValuesOverrideOnlyTheirFields) {
  VariationOverrides overrides;
  overrides.sway_amount = 0.9;
  overrides.breath_depth = 0.0;
  const VariationParams drawn = draw_variation(42);
  const VariationParams resolved = resolve_variation(42, overrides);
  EXPECT_EQ(resolved.sway_amount, 0.9);
  EXPECT_EQ(resolved.breath_depth, 0.0);
  EXPECT_EQ(resolved.sway_period, drawn.sway_period);
  EXPECT_EQ(resolved.cue_strength, drawn.cue_strength);
  EXPECT_EQ(resolved.reaction, drawn.reaction);
}

}  // namespace
}  // namespace tutti::ensemble_variation
