// SPDX-License-Identifier: MIT
#include <tutti/spline_motion/taut_string.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "corridor_cases.hpp"

namespace tutti::spline_motion {
namespace {

using piano_model::HandCorridors;
using testing::certificate;
using testing::random_corridors;

std::vector<PathPoint> string_of(const HandCorridors& c) {
  const auto s = taut_string(c);
  EXPECT_TRUE(s.ok()) << (s.ok() ? "" : s.error().message);
  return s.ok() ? s->points : std::vector<PathPoint>{};
}

void expect_points(const std::vector<PathPoint>& got, const std::vector<PathPoint>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_DOUBLE_EQ(got[i].t_s, want[i].t_s) << "point " << i;
    EXPECT_DOUBLE_EQ(got[i].x_mm, want[i].x_mm) << "point " << i;
  }
}

TEST(TautString, EmptyInput) { EXPECT_TRUE(string_of({}).empty()); }

TEST(TautString, OneCorridorHoldsTheMiddle) {
  expect_points(string_of({{1.0, 2.0, 10.0, 20.0}}), {{1.0, 15.0}, {2.0, 15.0}});
}

TEST(TautString, ZeroLengthCorridorIsOnePoint) {
  expect_points(string_of({{1.0, 1.0, 10.0, 20.0}}), {{1.0, 15.0}});
}

TEST(TautString, CommonRangeGivesAStraightFlatLine) {
  expect_points(string_of({{0, 1, 0, 10}, {2, 3, 5, 20}, {3, 4, 7, 9}}), {{0, 8}, {4, 8}});
}

TEST(TautString, SlopedStraightLineWithFlatEnds) {
  // Must be <= 10 at t=1, >= 20 at 2, <= 30 at 3, >= 40 at 4: one straight rise of 10 mm/s.
  expect_points(string_of({{0, 1, 0, 10}, {2, 3, 20, 30}, {4, 5, 40, 50}}),
                {{0, 10}, {1, 10}, {4, 40}, {5, 40}});
}

TEST(TautString, CrossesAWideCorridorDiagonally) {
  expect_points(string_of({{0, 1, 0, 10}, {1.5, 2.5, 0, 100}, {3, 4, 90, 100}}),
                {{0, 10}, {1, 10}, {3, 90}, {4, 90}});
}

TEST(TautString, ZigZagBendsAtCorridorEdges) {
  expect_points(string_of({{0, 1, 0, 10}, {2, 3, 50, 60}, {4, 5, 0, 10}, {6, 7, 50, 60}}),
                {{0, 10}, {1, 10}, {2, 50}, {3, 50}, {4, 10}, {5, 10}, {6, 50}, {7, 50}});
}

TEST(TautString, BendsAroundAnUpperAndALowerEdgeInsideOneRise) {
  // From 0 up to 100; a ceiling at t=2 (<= 20) and a floor at t=6 (>= 90) shape the rise.
  const auto p = string_of({{0, 0, 0, 0}, {2, 2, 0, 20}, {6, 6, 90, 200}, {8, 8, 100, 100}});
  expect_points(p, {{0, 0}, {2, 20}, {6, 90}, {8, 100}});
}

TEST(TautString, DegenerateWidthAndTouchingCorridors) {
  // lo == hi everywhere: the string must go through every point exactly.
  const HandCorridors c{{0, 1, 5, 5}, {1, 2, 5, 5}, {3, 3, 8, 8}, {4, 5, 2, 2}};
  expect_points(string_of(c), {{0, 5}, {2, 5}, {3, 8}, {4, 2}, {5, 2}});
}

TEST(TautString, TouchingCorridorsUseTheirIntersection) {
  const HandCorridors c{{0, 1, 0, 10}, {1, 2, 8, 30}, {2, 3, 25, 30}};
  // at t=1 only [8, 10]; at t=2 only [25, 30].
  expect_points(string_of(c), {{0, 10}, {1, 10}, {2, 25}, {3, 25}});
}

TEST(TautString, PositionInterpolatesAndHolds) {
  const auto s = taut_string(HandCorridors{{0, 1, 0, 10}, {2, 3, 20, 30}, {4, 5, 40, 50}});
  ASSERT_TRUE(s.ok());
  EXPECT_DOUBLE_EQ(s->position(-5.0), 10.0);
  EXPECT_DOUBLE_EQ(s->position(2.5), 25.0);
  EXPECT_DOUBLE_EQ(s->position(9.0), 40.0);
  EXPECT_NEAR(s->length(), 2.0 + std::hypot(3.0, 30.0), 1e-12);
}

TEST(TautString, RandomSequencesPassTheOptimalityCertificate) {
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
    const HandCorridors c = random_corridors(seed, 1 + static_cast<int>(seed % 60));
    const auto portals = corridor_portals(c);
    ASSERT_TRUE(portals.ok()) << portals.error().message;
    const TautString s = taut_string(std::span<const Portal>(*portals));
    ASSERT_EQ(certificate(s, *portals), "") << "seed " << seed;
  }
}

TEST(TautString, NarrowTubeCertificate) {
  // Zero-width and very narrow corridors, all touching: the string is forced almost everywhere.
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    HandCorridors c;
    double x = 0.0;
    for (int i = 0; i < 50; ++i) {
      x += 3.0 * u(rng);
      const double w = seed % 3 == 0 ? 0.0 : 0.5 * (u(rng) + 1.0);
      c.push_back({double(i), double(i) + (seed % 2 == 1 ? 1.0 : 0.0), x - w, x + w});
      if (seed % 2 == 1 && i > 0 && (c[i].lo_mm > c[i - 1].hi_mm || c[i].hi_mm < c[i - 1].lo_mm)) {
        c[i].lo_mm = std::min(c[i].lo_mm, c[i - 1].hi_mm);
        c[i].hi_mm = std::max(c[i].hi_mm, c[i - 1].lo_mm);
      }
    }
    const auto portals = corridor_portals(c);
    ASSERT_TRUE(portals.ok()) << portals.error().message;
    ASSERT_EQ(certificate(taut_string(std::span<const Portal>(*portals)), *portals), "")
        << "seed " << seed;
  }
}

TEST(TautString, HundredThousandCorridors) {
  // Linear time is measured by hand_path_benchmark; here: it works at scale and stays optimal.
  const HandCorridors c = random_corridors(42, 100'000);
  const auto portals = corridor_portals(c);
  ASSERT_TRUE(portals.ok());
  const TautString s = taut_string(std::span<const Portal>(*portals));
  EXPECT_EQ(certificate(s, *portals), "");
  EXPECT_GT(s.points.size(), 1000U);
}

TEST(TautString, ValidationErrorsPassThrough) {
  const auto s = taut_string(HandCorridors{{0, 1, 0, 1}, {2, 3, 4, 1}});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().message, "hand corridor 1: lo_mm 4 > hi_mm 1");
}

}  // namespace
}  // namespace tutti::spline_motion
