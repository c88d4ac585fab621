// The hand's move in toward the fallboard for black keys: at least as far in as every held key
// needs, eased in before and out after, short dips bridged, and nothing without a need.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <tutti/finger_motion/hand_reach_in.hpp>

namespace tutti::finger_motion {
namespace {

constexpr double kRampS = 0.15;
constexpr double kBridgeS = 0.4;

TEST(HandReachIn, NoNeedsStayAtTheRestLine) {
  const HandReachIn path = plan_reach_in({}, kRampS, kBridgeS);
  EXPECT_EQ(evaluate_reach_in(path, 0.0), 0.0);
  EXPECT_EQ(evaluate_reach_in(path, 10.0), 0.0);
  const HandReachIn none = plan_reach_in({{1.0, 2.0, 0.0}, {3.0, 4.0, -5.0}}, kRampS, kBridgeS);
  EXPECT_EQ(evaluate_reach_in(none, 1.5), 0.0);
  EXPECT_EQ(evaluate_reach_in(none, 3.5), 0.0);
}

TEST(HandReachIn, OneNeedIsHeldWholeAndEasedInBeforeAndOutAfter) {
  const HandReachIn path = plan_reach_in({{1.0, 2.0, 10.0}}, kRampS, kBridgeS);
  EXPECT_EQ(evaluate_reach_in(path, 1.0 - kRampS - 1e-6), 0.0);
  const double rising = evaluate_reach_in(path, 1.0 - 0.5 * kRampS);
  EXPECT_GT(rising, 0.0);
  EXPECT_LT(rising, 10.0);
  for (double t = 1.0; t <= 2.0; t += 0.01) EXPECT_EQ(evaluate_reach_in(path, t), 10.0) << t;
  const double falling = evaluate_reach_in(path, 2.0 + 0.5 * kRampS);
  EXPECT_GT(falling, 0.0);
  EXPECT_LT(falling, 10.0);
  EXPECT_EQ(evaluate_reach_in(path, 2.0 + kRampS + 1e-6), 0.0);
}

TEST(HandReachIn, AShortDipBetweenTwoNeedsIsBridgedALongOneIsNot) {
  const HandReachIn bridged = plan_reach_in({{1.0, 1.5, 10.0}, {1.7, 2.2, 8.0}}, kRampS, kBridgeS);
  // At least the lower of the two, not out and back.
  EXPECT_GE(evaluate_reach_in(bridged, 1.6), 8.0);
  EXPECT_LE(evaluate_reach_in(bridged, 1.6), 10.0);
  const HandReachIn apart = plan_reach_in({{1.0, 1.5, 10.0}, {2.5, 3.0, 8.0}}, kRampS, kBridgeS);
  EXPECT_EQ(evaluate_reach_in(apart, 2.0), 0.0);
}

// The invariant evaluate keeps on random needs: never less in than a need active at t, never
// further in than the largest need, and continuous (no jump of more than the ramp allows).
TEST(HandReachIn, NeverShortOfAHeldNeedOnRandomNeeds) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> start(0.0, 20.0), length(0.01, 1.5), depth(-5.0, 40.0);
  for (int round = 0; round < 20; ++round) {
    std::vector<ReachInNeed> needs;
    for (int k = 0; k < 40; ++k) {
      const double from = start(random);
      needs.push_back({from, from + length(random), depth(random)});
    }
    const HandReachIn path = plan_reach_in(needs, kRampS, kBridgeS);
    double most = 0.0;
    for (const ReachInNeed& n : needs) most = std::max(most, n.in_mm);
    double last = evaluate_reach_in(path, -1.0);
    for (double t = -1.0; t < 23.0; t += 0.001) {
      const double in = evaluate_reach_in(path, t);
      for (const ReachInNeed& n : needs) {
        if (t >= n.from_s && t <= n.to_s) {
          ASSERT_GE(in, n.in_mm - 1e-9) << "round " << round << " t " << t;
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
}  // namespace tutti::finger_motion
