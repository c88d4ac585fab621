// SPDX-License-Identifier: MIT
#include <tutti/spline_motion/corridor_portals.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

namespace tutti::spline_motion {
namespace {

using piano_model::HandCorridor;
using piano_model::HandCorridors;
using ::testing::HasSubstr;

TEST(CorridorPortals, EmptyInputGivesNoPortals) {
  const auto portals = corridor_portals({});
  ASSERT_TRUE(portals.ok());
  EXPECT_TRUE(portals->empty());
}

TEST(CorridorPortals, TwoPortalsPerCorridorOneForZeroLength) {
  const HandCorridors c{{0.0, 1.0, 10.0, 20.0}, {2.0, 2.0, 15.0, 15.0}};
  const auto portals = corridor_portals(c);
  ASSERT_TRUE(portals.ok());
  ASSERT_EQ(portals->size(), 3U);
  EXPECT_EQ((*portals)[2].t_s, 2.0);
  EXPECT_EQ((*portals)[2].lo_mm, 15.0);
  EXPECT_EQ((*portals)[2].corridor, 1U);
}

TEST(CorridorPortals, TouchingCorridorsIntersect) {
  const HandCorridors c{{0.0, 1.0, 10.0, 20.0}, {1.0, 2.0, 15.0, 30.0}, {2.0, 2.0, 16.0, 40.0}};
  const auto portals = corridor_portals(c);
  ASSERT_TRUE(portals.ok());
  ASSERT_EQ(portals->size(), 3U);
  EXPECT_EQ((*portals)[1].lo_mm, 15.0);
  EXPECT_EQ((*portals)[1].hi_mm, 20.0);
  EXPECT_EQ((*portals)[2].lo_mm, 16.0);
  EXPECT_EQ((*portals)[2].hi_mm, 30.0);
}

TEST(CorridorPortals, TouchingDisjointRangesAreAJump) {
  const HandCorridors c{{0.0, 1.0, 10.0, 20.0}, {1.0, 2.0, 25.0, 30.0}};
  const auto portals = corridor_portals(c);
  ASSERT_FALSE(portals.ok());
  EXPECT_THAT(portals.error().message, HasSubstr("hand corridors 0 and 1 meet at t=1 s"));
  EXPECT_THAT(portals.error().message, HasSubstr("jump"));
}

struct BadCase {
  HandCorridors corridors;
  const char* expected;
};

TEST(CorridorPortals, ValidationNamesTheIndex) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const BadCase cases[] = {
      {{{0, 1, 0, 1}, {2, 3, nan, 1}}, "hand corridor 1: non-finite value"},
      {{{0, inf, 0, 1}}, "hand corridor 0: non-finite value"},
      {{{0, 1, 0, 1}, {1, 2, 0, 1}, {3, 2, 0, 1}}, "hand corridor 2: start_s 3 > end_s 2"},
      {{{0, 1, 5, 4}}, "hand corridor 0: lo_mm 5 > hi_mm 4"},
      {{{0, 1, 0, 1}, {0.5, 2, 0, 1}},
       "hand corridor 1: start_s 0.5 is before the end of corridor 0 (1)"},
      {{{2, 3, 0, 1}, {0, 1, 0, 1}}, "hand corridor 1: start_s 0 is before the end of corridor 0"},
  };
  for (const BadCase& bad : cases) {
    const auto portals = corridor_portals(bad.corridors);
    ASSERT_FALSE(portals.ok()) << bad.expected;
    EXPECT_THAT(portals.error().message, HasSubstr(bad.expected));
    EXPECT_FALSE(validate_corridors(bad.corridors).ok());
  }
}

}  // namespace
}  // namespace tutti::spline_motion
