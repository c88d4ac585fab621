// SPDX-License-Identifier: MIT
// The plateau envelope (the pianist's hand moving in for black keys, the trombonist turning for the
// far slide positions): at least as high as every need, eased in before and out after, short
// dips bridged, and nothing without a need.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <tutti/spline_motion/plateau_envelope.hpp>

namespace tutti::spline_motion {
namespace {

constexpr double kRampS = 0.15;
constexpr double kBridgeS = 0.4;

TEST(PlateauEnvelope, NoNeedsStayAtTheRestLine) {
  const PlateauEnvelope path = plan_plateau_envelope({}, kRampS, kBridgeS);
  EXPECT_EQ(evaluate_plateau_envelope(path, 0.0), 0.0);
  EXPECT_EQ(evaluate_plateau_envelope(path, 10.0), 0.0);
  const PlateauEnvelope none = plan_plateau_envelope({{1.0, 2.0, 0.0}, {3.0, 4.0, -5.0}}, kRampS, kBridgeS);
  EXPECT_EQ(evaluate_plateau_envelope(none, 1.5), 0.0);
  EXPECT_EQ(evaluate_plateau_envelope(none, 3.5), 0.0);
}

TEST(PlateauEnvelope, OneNeedIsHeldWholeAndEasedInBeforeAndOutAfter) {
  const PlateauEnvelope path = plan_plateau_envelope({{1.0, 2.0, 10.0}}, kRampS, kBridgeS);
  EXPECT_EQ(evaluate_plateau_envelope(path, 1.0 - kRampS - 1e-6), 0.0);
  const double rising = evaluate_plateau_envelope(path, 1.0 - 0.5 * kRampS);
  EXPECT_GT(rising, 0.0);
  EXPECT_LT(rising, 10.0);
  for (double t = 1.0; t <= 2.0; t += 0.01) EXPECT_EQ(evaluate_plateau_envelope(path, t), 10.0) << t;
  const double falling = evaluate_plateau_envelope(path, 2.0 + 0.5 * kRampS);
  EXPECT_GT(falling, 0.0);
  EXPECT_LT(falling, 10.0);
  EXPECT_EQ(evaluate_plateau_envelope(path, 2.0 + kRampS + 1e-6), 0.0);
}

TEST(PlateauEnvelope, AShortDipBetweenTwoNeedsIsBridgedALongOneIsNot) {
  const PlateauEnvelope bridged = plan_plateau_envelope({{1.0, 1.5, 10.0}, {1.7, 2.2, 8.0}}, kRampS, kBridgeS);
  // At least the lower of the two, not out and back.
  EXPECT_GE(evaluate_plateau_envelope(bridged, 1.6), 8.0);
  EXPECT_LE(evaluate_plateau_envelope(bridged, 1.6), 10.0);
  const PlateauEnvelope apart = plan_plateau_envelope({{1.0, 1.5, 10.0}, {2.5, 3.0, 8.0}}, kRampS, kBridgeS);
  EXPECT_EQ(evaluate_plateau_envelope(apart, 2.0), 0.0);
}

// The invariant evaluate keeps on random needs: never less in than a need active at t, never
// further in than the largest need, and continuous (no jump of more than the ramp allows).
TEST(PlateauEnvelope, NeverShortOfAHeldNeedOnRandomNeeds) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> start(0.0, 20.0), length(0.01, 1.5), depth(-5.0, 40.0);
  for (int round = 0; round < 20; ++round) {
    std::vector<EnvelopeNeed> needs;
    for (int k = 0; k < 40; ++k) {
      const double from = start(random);
      needs.push_back({from, from + length(random), depth(random)});
    }
    const PlateauEnvelope path = plan_plateau_envelope(needs, kRampS, kBridgeS);
    double most = 0.0;
    for (const EnvelopeNeed& n : needs) most = std::max(most, n.value);
    double last = evaluate_plateau_envelope(path, -1.0);
    for (double t = -1.0; t < 23.0; t += 0.001) {
      const double in = evaluate_plateau_envelope(path, t);
      for (const EnvelopeNeed& n : needs) {
        if (t >= n.from_s && t <= n.to_s) {
          ASSERT_GE(in, n.value - 1e-9) << "round " << round << " t " << t;
        }
      }
      ASSERT_LE(in, most + 1e-9);
      ASSERT_GE(in, 0.0);
      // A ramp's fastest: 1.875 x 40 mm / 0.15 s = 0.5 mm per millisecond.
      ASSERT_LE(std::abs(in - last), 0.51) << "a jump at " << t;
      last = in;
    }
  }
}

}  // namespace
}  // namespace tutti::spline_motion
