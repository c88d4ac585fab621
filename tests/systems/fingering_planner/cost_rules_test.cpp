// SPDX-License-Identifier: MIT
// The paper's rules (Sekiguchi & Eiho 1999) on small hand-made cases, through the same cost
// functions the planners use.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <tutti/fingering_planner/transition_cost.hpp>
#include "planner_test_util.hpp"

namespace tutti::fingering_planner {
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

// The default preset's scale anchors: the thumb on the tonic, and on the fourth from the tonic
// towards the little finger (F for the right hand in C major, G for the left).
TEST(DefaultRules, ThumbOnTheTonicAndOnTheFourthTowardsTheLittleFinger) {
  const auto& m = test::model("default");
  const CostWeights& w = m.weights;
  ASSERT_LT(w.thumb_on_fourth, 0.0);
  auto thumb = [&](int key, Hand side, int tonic) {
    const EventFingering e = make_event_fingering(std::vector<FingeredKey>{{key, 1}}, side, m);
    return strike_cost(e, m, tonic) - strike_cost(e, m);
  };
  EXPECT_DOUBLE_EQ(thumb(60, Hand::right, 0), w.thumb_on_tonic);
  EXPECT_DOUBLE_EQ(thumb(60, Hand::left, 0), w.thumb_on_tonic);
  EXPECT_DOUBLE_EQ(thumb(65, Hand::right, 0), w.thumb_on_fourth);  // F above C
  EXPECT_DOUBLE_EQ(thumb(55, Hand::left, 0), w.thumb_on_fourth);   // G below C
  EXPECT_DOUBLE_EQ(thumb(67, Hand::right, 0), 0.0);
  EXPECT_DOUBLE_EQ(thumb(53, Hand::left, 0), 0.0);
  EXPECT_DOUBLE_EQ(thumb(62, Hand::right, 9), w.thumb_on_fourth);  // A minor: D
  EXPECT_DOUBLE_EQ(thumb(64, Hand::left, 9), w.thumb_on_fourth);   // and E below
  EXPECT_DOUBLE_EQ(thumb(66, Hand::right, 1), 0.0);                // F# is black: no anchor there
  EXPECT_DOUBLE_EQ(thumb(65, Hand::right, -1), 0.0);               // tonic unknown
  // The hand given explicitly wins over what the area says.
  const EventFingering right_f =
      make_event_fingering(std::vector<FingeredKey>{{65, 1}}, Hand::right, m);
  EXPECT_DOUBLE_EQ(strike_cost(right_f, m, 0, Hand::left) - strike_cost(right_f, m), 0.0);
  // The paper has neither term.
  const auto& paper = test::model("paper");
  const EventFingering e =
      make_event_fingering(std::vector<FingeredKey>{{65, 1}}, Hand::right, paper);
  EXPECT_DOUBLE_EQ(strike_cost(e, paper, 0), strike_cost(e, paper));
}

TEST(DefaultRules, TheHandOfAnEventFollowsFromItsArea) {
  const auto& m = test::model("default");
  for (const Hand side : {Hand::right, Hand::left}) {
    for (int key = 50; key < 75; ++key) {
      const EventFingering thumb =
          make_event_fingering(std::vector<FingeredKey>{{key, 1}}, side, m);
      EXPECT_EQ(hand_of(thumb, m), side) << key;
    }
    // A chord with the thumb: C-E-G with 1-3-5 (right) or 5-3-1 (left).
    const bool right = side == Hand::right;
    const EventFingering chord = make_event_fingering(
        std::vector<FingeredKey>{{60, right ? 1 : 5}, {64, 3}, {67, right ? 5 : 1}}, side, m);
    EXPECT_EQ(hand_of(chord, m), side);
  }
  // No thumb: nothing to tell.
  EXPECT_FALSE(hand_of(make_event_fingering(std::vector<FingeredKey>{{60, 3}}, Hand::right, m), m));
}

}  // namespace
}  // namespace tutti::fingering_planner
