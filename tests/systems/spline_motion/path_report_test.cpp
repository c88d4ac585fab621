// SPDX-License-Identifier: MIT
#include <tutti/spline_motion/path_report.hpp>

#include <gtest/gtest.h>

#include <cstdio>

#include "corridor_cases.hpp"
#include <tutti/spline_motion/smoothing.hpp>

namespace tutti::spline_motion {
namespace {

using piano_model::HandCorridors;
using testing::random_corridors;

HandPath planned_path(const HandCorridors& c, SmoothingMode mode) {
  auto path = plan_hand_path(c, PlanOptions{mode});
  EXPECT_TRUE(path.ok()) << (path.ok() ? "" : path.error().message);
  return path.ok() ? std::move(path).value() : HandPath{};
}

TEST(PathReport, FindsAKnownViolation) {
  const HandCorridors c{{0, 1, 0, 10}};
  const HandPath flat = planned_path({{0, 1, 14, 14}}, SmoothingMode::monotone_quintic);
  const PathReport r = corridor_violations(flat, c);
  EXPECT_EQ(r.violating_corridors, 1U);
  EXPECT_NEAR(r.worst_violation_mm, 4.0, 1e-12);
  EXPECT_EQ(r.worst_corridor, 0U);
  EXPECT_EQ(r.peak_speed_mm_per_s, 0.0);
}

TEST(PathReport, PeaksOfAKnownPiece) {
  // One quintic rise of 30 mm in 1 s with zero end slopes: minimum-jerk profile, peak speed
  // 1.875 * 30 = 56.25 mm/s at the middle, peak acceleration 10/sqrt(3) * 30 mm/s^2.
  const HandPath path =
      planned_path({{0, 0, 0, 0}, {1, 1, 30, 30}}, SmoothingMode::monotone_quintic);
  const PathReport r = corridor_violations(path, HandCorridors{});
  EXPECT_NEAR(r.peak_speed_mm_per_s, 56.25, 1e-9);
  EXPECT_NEAR(r.peak_acceleration_mm_per_s2, 30.0 * 10.0 / std::sqrt(3.0), 1e-6);
}

struct Tally {
  int cases = 0;
  int cases_violating = 0;
  std::size_t corridors_violating = 0;
  double worst_mm = 0.0;
};

Tally tally(SmoothingMode mode, int cases, int corridors_per_case) {
  Tally t;
  for (int seed = 1; seed <= cases; ++seed) {
    const HandCorridors c = random_corridors(static_cast<std::uint64_t>(seed), corridors_per_case);
    const PathReport r = corridor_violations(planned_path(c, mode), c, ReportOptions{16, 1e-9});
    ++t.cases;
    t.cases_violating += r.violating_corridors > 0 ? 1 : 0;
    t.corridors_violating += r.violating_corridors;
    t.worst_mm = std::max(t.worst_mm, r.worst_violation_mm);
  }
  std::printf(
      "[ %-16s ] %d cases x %d corridors: %d cases / %zu corridors violated, worst %.3f mm\n",
      to_string(mode), t.cases, corridors_per_case, t.cases_violating, t.corridors_violating,
      t.worst_mm);
  return t;
}

TEST(PathReport, DefaultSmoothingNeverLeavesACorridor) {
  const Tally t = tally(SmoothingMode::monotone_quintic, 2000, 30);
  EXPECT_EQ(t.corridors_violating, 0U);
  EXPECT_EQ(t.worst_mm, 0.0);
}

TEST(PathReport, PchipAndTheStringNeverLeaveACorridor) {
  EXPECT_EQ(tally(SmoothingMode::pchip, 500, 30).corridors_violating, 0U);
  EXPECT_EQ(tally(SmoothingMode::none, 500, 30).corridors_violating, 0U);
}

TEST(PathReport, NaturalSplineOvershootsOnCloseBends) {
  // The paper's smoothing: on the same kind of input it leaves corridors regularly.
  const Tally t = tally(SmoothingMode::natural_spline, 1000, 30);
  EXPECT_GT(t.cases_violating, 500);
  EXPECT_GT(t.worst_mm, 1.0);
}

TEST(PathReport, NaturalSplineOvershootHandMade) {
  // A quick 100 mm shift between two long holds: bends 10 ms apart.
  const HandCorridors c{{0, 1, 0, 0}, {1.01, 2, 100, 100}, {2.01, 3, 0, 0}};
  const PathReport natural = corridor_violations(planned_path(c, SmoothingMode::natural_spline), c);
  const PathReport quintic =
      corridor_violations(planned_path(c, SmoothingMode::monotone_quintic), c);
  EXPECT_EQ(natural.violating_corridors, 3U);
  EXPECT_GT(natural.worst_violation_mm, 10.0);
  EXPECT_EQ(quintic.violating_corridors, 0U);
}

}  // namespace
}  // namespace tutti::spline_motion
