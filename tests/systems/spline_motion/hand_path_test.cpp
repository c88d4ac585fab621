// SPDX-License-Identifier: MIT
#include <tutti/spline_motion/hand_path.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "corridor_cases.hpp"
#include <tutti/spline_motion/smoothing.hpp>

namespace tutti::spline_motion {
namespace {

using piano_model::HandCorridors;
using testing::random_corridors;

HandPath plan(const HandCorridors& c, SmoothingMode mode = SmoothingMode::monotone_quintic) {
  auto path = plan_hand_path(c, PlanOptions{mode});
  EXPECT_TRUE(path.ok()) << (path.ok() ? "" : path.error().message);
  return path.ok() ? std::move(path).value() : HandPath{};
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(HandPath, EmptyPathIsAtRestAtZero) {
  const HandPath path = plan({});
  EXPECT_TRUE(path.empty());
  const HandState s = evaluate(path, 3.0);
  EXPECT_EQ(s.x_mm, 0.0);
  EXPECT_EQ(s.v_mm_per_s, 0.0);
  EXPECT_EQ(s.a_mm_per_s2, 0.0);
}

TEST(HandPath, SingleZeroLengthCorridorHoldsEverywhere) {
  const HandPath path = plan({{1.0, 1.0, 10.0, 30.0}});
  for (const double t : {-1.0, 1.0, 2.0}) EXPECT_EQ(evaluate(path, t).x_mm, 20.0);
}

TEST(HandPath, HoldsStillBeforeAndAfter) {
  const HandPath path = plan({{0, 1, 0, 10}, {2, 3, 20, 30}, {4, 5, 40, 50}});
  const HandState before = evaluate(path, -100.0);
  const HandState after = evaluate(path, 100.0);
  EXPECT_EQ(before.x_mm, 10.0);
  EXPECT_EQ(before.v_mm_per_s, 0.0);
  EXPECT_EQ(after.x_mm, 40.0);
  EXPECT_EQ(after.a_mm_per_s2, 0.0);
  EXPECT_EQ(evaluate(path, std::numeric_limits<double>::quiet_NaN()).x_mm, 10.0);
  EXPECT_EQ(evaluate(path, std::numeric_limits<double>::infinity()).x_mm, 40.0);
  // The straight part of the taut string stays exactly straight (collinear knots).
  EXPECT_NEAR(evaluate(path, 2.5).x_mm, 25.0, 1e-9);
  EXPECT_NEAR(evaluate(path, 2.5).v_mm_per_s, 10.0, 1e-9);
}

TEST(HandPath, EvaluateIsDeterministic) {
  const HandPath path = plan(random_corridors(7, 200));
  const HandPath copy = path;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(path.start_s() - 1.0, path.end_s() + 1.0);
  for (int i = 0; i < 5000; ++i) {
    const double t = u(rng);
    const HandState a = evaluate(path, t);
    const HandState b = evaluate(path, t);
    const HandState c = evaluate(copy, t);
    ASSERT_TRUE(same_bits(a.x_mm, b.x_mm) && same_bits(a.v_mm_per_s, b.v_mm_per_s) &&
                same_bits(a.a_mm_per_s2, b.a_mm_per_s2) && same_bits(a.x_mm, c.x_mm) &&
                same_bits(a.a_mm_per_s2, c.a_mm_per_s2));
  }
}

// Value, velocity (and acceleration for C2) agree where pieces meet, relative to the size of
// the numbers involved; and evaluate()'s velocity matches a central difference of positions.
void check_continuity(const HandPath& path, bool c2, std::uint64_t seed) {
  const auto knots = path.knot_times();
  const auto pieces = path.pieces();
  for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
    const double h = knots[k + 1] - knots[k];
    const Poly5& a = pieces[k];
    const Poly5& b = pieces[k + 1];
    const double xs = 1.0 + std::abs(a.c[0]) + std::abs(b.c[0]);
    ASSERT_NEAR(a.value(h), b.value(0.0), 1e-9 * xs) << "seed " << seed << " knot " << k + 1;
    const double vs = 1.0 + std::abs(a.c[1]) * 1e-3 + std::abs(b.c[1]) + xs / h;
    ASSERT_NEAR(a.velocity(h), b.velocity(0.0), 1e-7 * vs) << "seed " << seed << " knot " << k + 1;
    if (c2) {
      ASSERT_NEAR(a.acceleration(h), 0.0, 1e-6 * vs / h) << "seed " << seed;
      ASSERT_EQ(b.acceleration(0.0), 0.0) << "seed " << seed;
    }
  }
  // Rest at both ends: continuous with the holds.
  if (!pieces.empty()) {
    EXPECT_EQ(pieces.front().velocity(0.0), 0.0);
    const double h = knots.back() - knots[knots.size() - 2];
    EXPECT_NEAR(pieces.back().velocity(h), 0.0, 1e-6 * (1.0 + 1000.0 / h));
  }
  // Numerical derivative through evaluate(), at points away from knots.
  for (std::size_t k = 0; k < pieces.size(); k += 7) {
    const double h = knots[k + 1] - knots[k];
    if (h < 1e-3) continue;
    const double t = knots[k] + 0.37 * h;
    const double e = 1e-6 * h;
    const double fd = (evaluate(path, t + e).x_mm - evaluate(path, t - e).x_mm) / (2 * e);
    const double v = evaluate(path, t).v_mm_per_s;
    ASSERT_NEAR(fd, v, 1e-4 * (1.0 + std::abs(v)) + 1e-6 / h) << "seed " << seed;
  }
}

TEST(HandPath, MonotoneQuinticIsC2) {
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    check_continuity(plan(random_corridors(seed, 40)), true, seed);
  }
}

TEST(HandPath, PchipAndNaturalSplineAreC1) {
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    check_continuity(plan(random_corridors(seed, 40), SmoothingMode::pchip), false, seed);
    const HandPath natural = plan(random_corridors(seed, 40), SmoothingMode::natural_spline);
    const auto knots = natural.knot_times();
    const auto pieces = natural.pieces();
    for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
      const double h = knots[k + 1] - knots[k];
      const double scale = 1.0 + std::abs(pieces[k].velocity(h)) + std::abs(pieces[k].c[0]) / h;
      ASSERT_NEAR(pieces[k].velocity(h), pieces[k + 1].velocity(0.0), 1e-7 * scale);
      ASSERT_NEAR(pieces[k].acceleration(h), pieces[k + 1].acceleration(0.0), 1e-5 * scale / h);
    }
  }
}

TEST(HandPath, DefaultNeverOvershootsTheKnotValues) {
  // Each piece stays between its two knot values (checked on the raw polynomial).
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const HandPath path = plan(random_corridors(seed, 40));
    const auto knots = path.knot_times();
    const auto pieces = path.pieces();
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      const double x0 = pieces[k].c[0];
      const double x1 = k + 1 < pieces.size() ? pieces[k + 1].c[0] : path.end_x_mm();
      const auto [lo, hi] = pieces[k].range(0, 0.0, knots[k + 1] - knots[k], 64);
      ASSERT_GE(lo, std::min(x0, x1) - 1e-9) << "seed " << seed << " piece " << k;
      ASSERT_LE(hi, std::max(x0, x1) + 1e-9) << "seed " << seed << " piece " << k;
    }
  }
}

TEST(HandPath, ModesAgreeOnKnotsOfTheString) {
  const HandCorridors c{{0, 1, 0, 10}, {2, 3, 50, 60}, {4, 5, 0, 10}};
  for (const SmoothingMode mode : {SmoothingMode::monotone_quintic, SmoothingMode::pchip,
                                   SmoothingMode::natural_spline, SmoothingMode::none}) {
    const HandPath path = plan(c, mode);
    EXPECT_EQ(path.mode(), mode);
    EXPECT_NEAR(evaluate(path, 1.0).x_mm, 10.0, 1e-9) << to_string(mode);
    EXPECT_NEAR(evaluate(path, 2.0).x_mm, 50.0, 1e-9) << to_string(mode);
  }
}

TEST(HandPath, SmoothingModeNamesRoundTrip) {
  for (const SmoothingMode mode : {SmoothingMode::monotone_quintic, SmoothingMode::pchip,
                                   SmoothingMode::natural_spline, SmoothingMode::none}) {
    const auto parsed = smoothing_mode_from_string(to_string(mode));
    ASSERT_TRUE(parsed.has_value()) << to_string(mode);
    EXPECT_EQ(*parsed, mode);
  }
  EXPECT_EQ(std::string(to_string(SmoothingMode::natural_spline)), "natural_spline");
  for (const char* bad : {"", "?", "natural", "Pchip", "monotone_quintic ", "default"}) {
    EXPECT_FALSE(smoothing_mode_from_string(bad).has_value()) << bad;
  }
}

TEST(HandPath, PlanReportsValidationErrors) {
  const auto path = plan_hand_path(HandCorridors{{0, 1, 0, 1}, {0.5, 1, 0, 1}});
  ASSERT_FALSE(path.ok());
  EXPECT_NE(path.error().message.find("hand corridor 1"), std::string::npos);
}

TEST(HandPath, KnotsTooCloseForPolynomialsAreAnError) {
  const double t = 1.0;
  const double next = std::nextafter(t, 2.0);
  const auto path = plan_hand_path(HandCorridors{{0, t, 0, 1}, {next, 2, 1e300, 1e300}});
  // Either a finite path or a clear error, never infinities.
  if (path.ok()) {
    for (const Poly5& p : path->pieces()) {
      for (const double c : p.c) EXPECT_TRUE(std::isfinite(c));
    }
  } else {
    EXPECT_NE(path.error().message.find("too close"), std::string::npos);
  }
}

}  // namespace
}  // namespace tutti::spline_motion
