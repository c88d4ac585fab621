// SPDX-License-Identifier: MIT
// The other hand's room (other_hand_cost.hpp): a hand's fingering keeps it on its own side of the
// other hand, measured on the planned corridors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include <tutti/fingering_planner/exact_planner.hpp>
#include <tutti/fingering_planner/plan_score.hpp>
#include <tutti/music/load_score.hpp>
#include "planner_test_util.hpp"
#include "testdata.hpp"

namespace tutti::fingering_planner {
namespace {

using music::Hand;

double centre(const HandCorridor& c) { return 0.5 * (c.lo_mm + c.hi_mm); }

// How much nearer than `separation` white keys the left hand's corridor centres come to the
// right hand's, summed over every pair of corridors within `lead_s` of each other (white keys).
double crowding(const HandCorridors& left, const HandCorridors& right, const FingeringModel& m,
                double separation, double lead_s) {
  const double white = m.keyboard.white_key_width_mm();
  double sum = 0.0;
  for (const HandCorridor& l : left) {
    for (const HandCorridor& r : right) {
      if (r.start_s >= l.end_s + lead_s || r.end_s <= l.start_s - lead_s) continue;
      sum += std::max(0.0, centre(l) - (centre(r) - separation * white)) / white;
    }
  }
  return sum;
}

// Mozart's K. 545 (bar 41 of the third-party score): the right hand trills C4-D4 and leaps away
// as the left hand starts B3-D4 broken thirds. Alone, the left hand takes them 5-3, its palm over
// C4-F4 where the right hand still is; beside the right hand it starts 2-1 on its own side and
// takes 5-3 once the right hand has gone.
TEST(OtherHandCost, ALeftHandBesideTheRightHandsTrillKeepsToItsSide) {
  const FingeringModel& m = test::model("default");
  ASSERT_GT(m.weights.other_hand_per_white_key, 0.0);
  std::vector<PlanNote> right_notes, left;
  for (int i = 0; i < 8; ++i) {
    right_notes.push_back({i % 2 == 0 ? 60 : 62, 0.125 * i, 0.125 * (i + 1), 0});
  }
  right_notes.push_back({86, 1.0, 1.5, 0});
  for (int i = 0; i < 8; ++i) left.push_back({i % 2 == 0 ? 59 : 62, 1.0 + 0.125 * i, 1.0 + 0.125 * (i + 1), 0});
  auto right = plan_hand_exact(right_notes, Hand::right, m);
  ASSERT_TRUE(right.ok()) << right.error().message;
  auto alone = plan_hand_exact(left, Hand::left, m);
  auto beside = plan_hand_exact(left, Hand::left, m, right->corridors);
  ASSERT_TRUE(alone.ok() && beside.ok());
  const double before = crowding(alone->corridors, right->corridors, m, 4.0, 0.15);
  const double after = crowding(beside->corridors, right->corridors, m, 4.0, 0.15);
  EXPECT_GT(before, 0.0);
  EXPECT_LT(after, before) << "alone " << test::fingers_text(alone->fingers) << ", beside "
                           << test::fingers_text(beside->fingers);
  EXPECT_NE(alone->fingers, beside->fingers);
  std::printf("alone %s, beside %s\n", test::fingers_text(alone->fingers).c_str(),
              test::fingers_text(beside->fingers).c_str());
}

// Without the other hand, or with a zero weight, nothing changes.
TEST(OtherHandCost, AZeroWeightOrNoOtherHandChangesNothing) {
  FingeringModel m = test::model("default");
  std::vector<PlanNote> right_notes, left;
  for (int i = 0; i < 8; ++i) {
    right_notes.push_back({i % 2 == 0 ? 60 : 62, 0.125 * i, 0.125 * (i + 1), 0});
    left.push_back({i % 2 == 0 ? 59 : 62, 1.0 + 0.125 * i, 1.0 + 0.125 * (i + 1), 0});
  }
  auto right = plan_hand_exact(right_notes, Hand::right, m);
  ASSERT_TRUE(right.ok());
  auto alone = plan_hand_exact(left, Hand::left, m);
  m.weights.other_hand_per_white_key = 0.0;
  auto unweighted = plan_hand_exact(left, Hand::left, m, right->corridors);
  ASSERT_TRUE(alone.ok() && unweighted.ok());
  EXPECT_EQ(alone->fingers, unweighted->fingers);
  EXPECT_DOUBLE_EQ(alone->total_cost, unweighted->total_cost);
}

// Third-party piano music: over whole pieces the left hand comes nearer the right hand less
// often than when each hand is planned alone (the default weights with the term switched off).
TEST(OtherHandCost, ThirdPartyLeftHandsCrowdTheRightHandLess) {
  TUTTI_REQUIRE_TESTDATA();
  const FingeringModel& with = test::model("default");
  FingeringModel without = with;
  without.weights.other_hand_per_white_key = 0.0;
  for (const char* file : {"musicxml/pianoplayer/mozart_sonfacile.mxl",
                           "musicxml/lilypond-test-suite/01a-Pitches-Pitches.xml",
                           "midi/tonejs/bach_846.mid", "musicxml/pianoplayer/bach_invention4.xml"}) {
    auto score = music::load_score(tutti::test::testdata(file));
    ASSERT_TRUE(score.ok()) << score.error().message;
    auto a = plan_score(*score, without);
    auto b = plan_score(*score, with);
    ASSERT_TRUE(a.ok() && b.ok()) << file;
    const double before = crowding(a->left.corridors, a->right.corridors, with, 4.0, 0.15);
    const double after = crowding(b->left.corridors, b->right.corridors, with, 4.0, 0.15);
    EXPECT_LT(after, before) << file;
    std::printf("%s: crowding %.1f -> %.1f white keys\n", file, before, after);
  }
}

}  // namespace
}  // namespace tutti::fingering_planner
