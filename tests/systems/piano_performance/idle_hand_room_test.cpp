// SPDX-License-Identifier: MIT
// A hand that is not playing moves out of the other hand's way: its idle gaps keep its thumb side
// a white key short of the other hand's thumb side (its reference point, or its lowest key when
// it stretches further), and nothing changes where the other hand is far or crosses over.
#include <tutti/piano_performance/idle_hand_room.hpp>

#include <gtest/gtest.h>

#include <limits>

#include <tutti/piano_performance/performance_plan.hpp>
#include <tutti/spline_motion/path_report.hpp>
#include <tutti/spline_motion/smoothing.hpp>

namespace tutti::piano_performance {
namespace {

using piano_model::HandCorridor;
using piano_model::HandCorridors;

// A corridor whose keys are known (the planner's): reference range and keys' extent, mm.
HandCorridor played(double from_s, double to_s, double lo, double hi, double keys_lo,
                    double keys_hi) {
  HandCorridor c{from_s, to_s, lo, hi};
  c.keys_known = true;
  c.keys_lo_mm = keys_lo;
  c.keys_hi_mm = keys_hi;
  return c;
}

spline_motion::HandPath path_through(const HandCorridors& corridors) {
  auto path = spline_motion::plan_hand_path(corridors);
  EXPECT_TRUE(path.ok()) << path.error().message;
  return path.ok() ? *path : spline_motion::HandPath{};
}

// The left hand plays at 500 mm, rests 1 s, plays at 500 mm again; meanwhile the right hand
// comes down to play with its lowest key at 520 mm and its reference point at 560 (its resting
// thumb at 513). Alone the left hand would wait at 500 mm, its own thumb side (547) past the
// right hand's: with room it moves down to 513 - 23.5 - 47 = 442.5 mm while the right hand plays
// there, and is back for its keys.
TEST(IdleHandRoom, TheIdleLeftHandMakesRoomForTheRightThumb) {
  const HandCorridors left{played(0.0, 0.5, 480.0, 500.0, 500.0, 500.0),
                           played(1.5, 2.0, 500.0, 520.0, 500.0, 500.0)};
  const HandCorridors right{played(0.0, 0.6, 700.0, 720.0, 700.0, 760.0),
                            played(0.8, 1.2, 560.0, 560.0, 520.0, 600.0),
                            played(1.4, 2.0, 700.0, 720.0, 700.0, 760.0)};
  const spline_motion::HandPath right_path = path_through(right);
  const HandCorridors with_room = with_idle_room(left, right, right_path, music::Hand::left);
  ASSERT_GT(with_room.size(), left.size());
  for (std::size_t i = 1; i < with_room.size(); ++i) {
    EXPECT_LE(with_room[i - 1].end_s, with_room[i].start_s) << i;  // still sorted, no overlap
  }
  const spline_motion::HandPath alone = path_through(left);
  const spline_motion::HandPath apart = path_through(with_room);
  EXPECT_NEAR(spline_motion::evaluate(alone, 1.0).x_mm, 500.0, 1e-6);
  EXPECT_LE(spline_motion::evaluate(apart, 1.0).x_mm, 560.0 - 47.0 - 23.5 - 47.0 + 1e-6);
  // Its own keys are still reached: every original corridor holds.
  EXPECT_EQ(spline_motion::corridor_violations(apart, left).violating_corridors, 0u);
}

// The right hand far above (its thumb side 300 mm away): the left hand's path is unchanged.
TEST(IdleHandRoom, AFarHandChangesNothing) {
  const HandCorridors left{played(0.0, 0.5, 480.0, 500.0, 500.0, 500.0),
                           played(1.5, 2.0, 500.0, 520.0, 500.0, 500.0)};
  const HandCorridors right{played(0.0, 2.0, 900.0, 920.0, 880.0, 960.0)};
  const spline_motion::HandPath right_path = path_through(right);
  const spline_motion::HandPath alone = path_through(left);
  const spline_motion::HandPath apart = path_through(with_idle_room(left, right, right_path, music::Hand::left));
  for (double t = 0.0; t <= 2.0; t += 0.05) {
    EXPECT_NEAR(spline_motion::evaluate(apart, t).x_mm, spline_motion::evaluate(alone, t).x_mm, 1e-6) << t;
  }
}

// A right hand whose keys lie below the left hand's middle (it crosses over to play there) keeps
// no room on its own side: nothing is added around those keys.
TEST(IdleHandRoom, ACrossingHandKeepsNoRoom) {
  const HandCorridors left{played(0.0, 3.0, 600.0, 620.0, 560.0, 660.0)};
  const HandCorridors right{played(0.0, 0.5, 900.0, 920.0, 880.0, 960.0),
                            played(1.5, 2.0, 400.0, 420.0, 380.0, 440.0)};
  const spline_motion::HandPath left_path = path_through(left);
  const HandCorridors with_room = with_idle_room(right, left, left_path, music::Hand::right);
  // Only the room after the crossing's end is not added either (the last corridor is crossed).
  EXPECT_EQ(with_room.size(), right.size());
}

// Input the planner never gives (unsorted, reversed, not finite) comes back unchanged, as does
// any input without the other hand's path.
TEST(IdleHandRoom, MalformedInputIsReturnedAsItIs) {
  const HandCorridors right{played(0.0, 2.0, 560.0, 580.0, 520.0, 600.0)};
  const spline_motion::HandPath right_path = path_through(right);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const HandCorridors& bad :
       {HandCorridors{{1.0, 2.0, 0.0, 10.0}, {0.0, 0.5, 0.0, 10.0}},
        HandCorridors{{0.0, 1.0, 10.0, 0.0}, {1.5, 2.0, 0.0, 10.0}},
        HandCorridors{{0.0, nan, 0.0, 10.0}, {1.5, 2.0, 0.0, 10.0}}}) {
    const HandCorridors out = with_idle_room(bad, right, right_path, music::Hand::left);
    ASSERT_EQ(out.size(), bad.size());
  }
  const HandCorridors left{played(0.0, 0.5, 480.0, 500.0, 500.0, 500.0),
                           played(1.5, 2.0, 500.0, 520.0, 500.0, 500.0)};
  EXPECT_EQ(with_idle_room(left, right, spline_motion::HandPath{}, music::Hand::left).size(), left.size());
}

}  // namespace
}  // namespace tutti::piano_performance
