// SPDX-License-Identifier: MIT
// evaluate_breath never allocates: this program counts allocations (allocation_counter.hpp) and
// evaluates many frames after planning.
#include <gtest/gtest.h>

#include <cmath>

#include "allocation_counter.hpp"
#include "breath_fixture.hpp"

namespace tutti::brass_motion {

// The brass model's names used here (systems/brass_model).
using brass_model::LineNote;

namespace {

TEST(EvaluateBreathAllocation, NoAllocationPerCall) {
  const music::Score score = test::score_at(120);
  std::vector<LineNote> notes;
  // Phrases of 12 quarters (some long enough for catch-breaths) and rests of every class.
  double q = 1;
  for (int phrase = 0; phrase < 20; ++phrase) {
    const int length = phrase % 3 == 0 ? 36 : 12;
    for (int i = 0; i < length; ++i, q += 1) notes.push_back(test::note_q(score, q, q + 1));
    q += 0.5 * (phrase % 5);
  }
  const BreathPlan plan = plan_breaths(test::line_of(notes), score, test::fixed_params());
  ASSERT_GT(plan.events.size(), 20u);
  ASSERT_GT(plan.catch_breaths, 0);
  const double end = notes.back().offset_s + 1.0;

  const long before = tutti::test::allocation_count();
  double sum = 0;
  for (int i = 0; i < 20000; ++i) {
    const BreathState s = evaluate_breath(plan, -2.0 + (end + 2.0) * i / 20000.0);
    sum += s.air + s.inhale + s.preparing + s.strain + s.breath_index;
  }
  const long after = tutti::test::allocation_count();
  EXPECT_EQ(after - before, 0);
  EXPECT_TRUE(std::isfinite(sum));
  // The counter works.
  auto* probe = new int(3);
  EXPECT_EQ(tutti::test::allocation_count(), after + 1);
  delete probe;
}

}  // namespace
}  // namespace tutti::brass_motion
