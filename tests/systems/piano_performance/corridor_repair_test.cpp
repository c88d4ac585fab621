// SPDX-License-Identifier: MIT
// The corridor repair: jumps get a transition gap, contract violations are fixed, and the result
// always plans.
#include <tutti/piano_performance/corridor_repair.hpp>

#include <gtest/gtest.h>

#include <limits>

#include <tutti/piano_performance/performance_plan.hpp>
#include <tutti/spline_motion/corridor_portals.hpp>
#include <tutti/spline_motion/path_report.hpp>
#include <tutti/spline_motion/smoothing.hpp>

namespace tutti::piano_performance {
namespace {

using piano_model::HandCorridor;

TEST(CorridorRepair, LegatoJumpOpensAGapOnBothSides) {
  // 1 s and 0.1 s corridors touching at t=1 with disjoint ranges.
  const piano_model::HandCorridors in{{0.0, 1.0, 0.0, 10.0}, {1.0, 1.1, 50.0, 60.0}};
  ASSERT_FALSE(spline_motion::corridor_portals(in).ok());  // the gap this repair exists for
  const CorridorRepair r = repair_corridors(in);
  EXPECT_EQ(r.jumps, 1);
  EXPECT_EQ(r.dropped, 0);
  ASSERT_EQ(r.corridors.size(), 2u);
  EXPECT_DOUBLE_EQ(r.corridors[0].end_s, 1.0 - 0.030);    // 30 ms cap
  EXPECT_DOUBLE_EQ(r.corridors[1].start_s, 1.0 + 0.025);  // 25% of 100 ms
  auto path = spline_motion::plan_hand_path(r.corridors);
  ASSERT_TRUE(path.ok()) << path.error().message;
  EXPECT_EQ(spline_motion::corridor_violations(*path, r.corridors).violating_corridors, 0u);
  EXPECT_GT(spline_motion::corridor_violations(*path, in).violating_corridors, 0u);
}

TEST(CorridorRepair, OverlappingRangesAreLeftAlone) {
  const piano_model::HandCorridors in{{0.0, 1.0, 0.0, 10.0}, {1.0, 2.0, 5.0, 60.0}};
  const CorridorRepair r = repair_corridors(in);
  EXPECT_EQ(r.total(), 0);
  EXPECT_DOUBLE_EQ(r.corridors[0].end_s, 1.0);
  EXPECT_DOUBLE_EQ(r.corridors[1].start_s, 1.0);
}

TEST(CorridorRepair, ZeroLengthCorridorStaysValid) {
  // A zero-length corridor between two long ones, disjoint from both.
  const piano_model::HandCorridors in{
      {0.0, 1.0, 0.0, 10.0}, {1.0, 1.0, 50.0, 60.0}, {1.0, 2.0, 100.0, 110.0}};
  const CorridorRepair r = repair_corridors(in);
  EXPECT_EQ(r.jumps, 2);
  ASSERT_EQ(r.corridors.size(), 3u);
  EXPECT_EQ(r.corridors[1].start_s, r.corridors[1].end_s);
  EXPECT_TRUE(spline_motion::corridor_portals(r.corridors).ok());
}

TEST(CorridorRepair, TwoZeroLengthDisjointAtOneInstantDropsTheLater) {
  const piano_model::HandCorridors in{{1.0, 1.0, 0.0, 10.0}, {1.0, 1.0, 50.0, 60.0}};
  const CorridorRepair r = repair_corridors(in);
  EXPECT_EQ(r.dropped, 1);
  ASSERT_EQ(r.corridors.size(), 1u);
  EXPECT_EQ(r.origin[0], 0u);
  EXPECT_TRUE(spline_motion::corridor_portals(r.corridors).ok());
}

TEST(CorridorRepair, ContractViolationsAreFixed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const piano_model::HandCorridors in{{2.0, 3.0, 10.0, 0.0},  // reversed range
                                      {0.0, 2.5, 0.0, 10.0},  // unsorted and overlapping the first
                                      {4.0, nan, 0.0, 1.0}};  // non-finite
  const CorridorRepair r = repair_corridors(in);
  EXPECT_EQ(r.dropped, 1);
  EXPECT_GE(r.sanitized, 2);
  ASSERT_EQ(r.corridors.size(), 2u);
  EXPECT_TRUE(spline_motion::corridor_portals(r.corridors).ok());
  EXPECT_FALSE(r.notes.empty());
}

TEST(CorridorRepair, MalformedCorridorsStillGiveAPathAndAReport) {
  const double inf = std::numeric_limits<double>::infinity();
  const piano_model::HandCorridors in{{0.0, 1.0, 0.0, 10.0},
                                      {1.0, 1.5, 40.0, 30.0},
                                      {1.2, 2.0, 100.0, 110.0},
                                      {3.0, 4.0, -inf, 5.0}};
  HandReport report;
  const spline_motion::HandPath path = plan_hand_motion(in, PerformanceOptions{}, report);
  EXPECT_TRUE(report.path_error.empty()) << report.path_error;
  EXPECT_FALSE(path.empty());
  EXPECT_EQ(report.against_used.violating_corridors, 0u);
  EXPECT_EQ(report.repair.dropped, 1);
  EXPECT_GE(report.repair.sanitized, 2);
  EXPECT_GE(report.repair.jumps, 1);
}

}  // namespace
}  // namespace tutti::piano_performance
