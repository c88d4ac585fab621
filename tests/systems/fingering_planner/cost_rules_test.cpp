// The paper's rules (Sekiguchi & Eiho 1999) on small hand-made cases, through the same cost
// functions the planners use.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fingering_planner/transition_cost.hpp"
#include "planner_test_util.hpp"

namespace tutti::piano {
namespace {

using music::Hand;

EventFingering at(std::vector<FingeredKey> keys, Hand side = Hand::right) {
  return make_event_fingering(keys, side, test::model("paper"));
}

TEST(PaperRules, SameFingerOnConsecutiveDifferentNotesIsInfinite) {
  const auto& m = test::model("paper");
  EXPECT_TRUE(std::isinf(transition_cost(at({{60, 2}}), at({{62, 2}}), 0.5, Hand::right, m)));
  EXPECT_TRUE(std::isinf(transition_cost(at({{60, 1}}), at({{64, 1}}), 5.0, Hand::right, m)));
  // The same finger on the same key (a repeated note) is allowed.
  EXPECT_DOUBLE_EQ(transition_cost(at({{60, 2}}), at({{60, 2}}), 0.0, Hand::right, m), 0.0);
}

TEST(PaperRules, ThumbCostsPointOnePerUseAndOnePointFiveMoreOnABlackKey) {
  const auto& m = test::model("paper");
  EXPECT_DOUBLE_EQ(strike_cost(at({{60, 1}}), m), 0.1);
  EXPECT_DOUBLE_EQ(strike_cost(at({{60, 2}}), m), 0.0);
  EXPECT_DOUBLE_EQ(strike_cost(at({{61, 1}}), m), 1.6);
  EXPECT_DOUBLE_EQ(strike_cost(at({{61, 3}}), m), 0.0);
  // A held thumb is not a new use.
  EXPECT_DOUBLE_EQ(strike_cost(at({{60, 1, true}, {64, 3}}), m), 0.0);
}

TEST(PaperRules, OverlapCostIsOneMinusOverlapOverWidestArea) {
  const auto& m = test::model("paper");
  // 3 on E4 -> area [E-1, E+1]; 1 on F4 -> [F-1, F+4.5] = [E, E+5.5]: overlap 1, widest 5.5.
  EXPECT_NEAR(transition_cost(at({{64, 3}}), at({{65, 1}}), 0.0, Hand::right, m), 1 - 1 / 5.5,
              1e-12);
  // 1 on C4 -> [C-1, C+4.5]; 2 on D4 -> [D-0.5, D+2] = [C+0.5, C+3]: overlap 2.5.
  EXPECT_NEAR(transition_cost(at({{60, 1}}), at({{62, 2}}), 0.0, Hand::right, m), 1 - 2.5 / 5.5,
              1e-12);
  // Same area: no cost.
  EXPECT_DOUBLE_EQ(transition_cost(at({{60, 1}}), at({{60, 1}}), 0.0, Hand::right, m), 0.0);
  // Chord area = intersection: C4-E4-G4 with 1-3-5: [C-1, C+4.5] ∩ [C+1, C+3] ∩ [C+0.5, C+3].
  const EventFingering chord = at({{60, 1}, {64, 3}, {67, 5}});
  EXPECT_NEAR((chord.lo_mm - m.keyboard.x_mm(60)) / 23.5, 1.0, 1e-12);
  EXPECT_NEAR((chord.hi_mm - m.keyboard.x_mm(60)) / 23.5, 3.0, 1e-12);
}

TEST(PaperRules, NonOverlappingMoveCostsAtLeastOneAndIsInfiniteWithoutTime) {
  const auto& m = test::model("paper");
  // 1 on C4 -> [C-1, C+4.5]; 5 on C6 -> [C+14-3.5, C+14-1] = [C+10.5, C+13]: gap 6 white keys.
  EXPECT_TRUE(std::isinf(transition_cost(at({{60, 1}}), at({{84, 5}}), 0.0, Hand::right, m)));
  EXPECT_NEAR(transition_cost(at({{60, 1}}), at({{84, 5}}), 1.0, Hand::right, m), 1.0 + 0.05 * 6,
              1e-9);
  EXPECT_NEAR(transition_cost(at({{60, 1}}), at({{84, 5}}), 0.5, Hand::right, m), 1.0 + 0.05 * 12,
              1e-9);
  EXPECT_GE(area_transition_cost(0, 1, 2, 3, 100.0, m), 1.0);
}

TEST(PaperRules, LeftHandIsTheMirrorImage) {
  const auto& m = test::model("paper");
  // Left thumb reaches [-1, +4.5] white keys from the reference point: area = [x - 4.5δ, x + δ].
  const EventFingering left = at({{60, 1}}, Hand::left);
  EXPECT_NEAR(left.lo_mm, m.keyboard.x_mm(60) - 4.5 * 23.5, 1e-9);
  EXPECT_NEAR(left.hi_mm, m.keyboard.x_mm(60) + 1.0 * 23.5, 1e-9);
  // Left 3 on E4 then thumb on D4 (thumb under, descending) = right 3 on E4 then 1 on F4.
  EXPECT_NEAR(
      transition_cost(at({{64, 3}}, Hand::left), at({{62, 1}}, Hand::left), 0.0, Hand::left, m),
      1 - 1 / 5.5, 1e-12);
}

}  // namespace
}  // namespace tutti::piano
