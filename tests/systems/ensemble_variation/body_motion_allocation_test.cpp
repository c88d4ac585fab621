// SPDX-License-Identifier: MIT
// evaluate_body_motion never allocates, with many cues and expression spans: this program counts
// allocations (allocation_counter.hpp) and evaluates many frames after planning.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "allocation_counter.hpp"
#include "ensemble_fixture.hpp"
#include <tutti/ensemble_variation/evaluate_body_motion.hpp>

namespace tutti::ensemble_variation {
namespace {

TEST(EvaluateBodyMotionAllocation, NoAllocationPerCallWithCuesAndExpressions) {
  const music::Score score = test::four_four();
  const test::Breaths breath = test::breaths({{3.0, 3.5, 4.0}, {11.0, 11.2, 11.6}});
  std::vector<PerformerInput> inputs = {test::player(score, breath, 1, true),
                                        test::player(score, breath, 2, false)};
  for (int i = 0; i < 40; ++i) {
    ExpressionSpan span;
    span.kind = i % 2 == 0 ? ExpressionKind::strain : ExpressionKind::relaxed;
    span.start_s = 0.75 * i;
    span.end_s = 0.75 * i + 0.5;
    span.amount = 0.5 + 0.01 * i;
    inputs[1].expressions.push_back(span);
  }
  EnsembleOptions options;
  options.cues_s = std::vector<double>{};
  for (int i = 0; i < 15; ++i) options.cues_s->push_back(2.0 + 2.0 * i);
  auto plan = plan_ensemble(inputs, options);
  ASSERT_TRUE(plan);
  ASSERT_EQ(plan->performers[1].cues.size(), 15u);
  ASSERT_EQ(plan->performers[1].expressions.size(), 40u);

  const long before = tutti::test::allocation_count();
  double sum = 0;
  for (int i = 0; i < 20000; ++i) {
    const double t = -2.0 + 34.0 * i / 20000.0;
    for (const PerformerMotionPlan& p : plan->performers) {
      const components::BodyMotion m = evaluate_body_motion(p, t, 0.3);
      sum += m.sway_rad + m.bell_lift_rad + m.shoulder_lift_m + m.strain;
    }
  }
  const long after = tutti::test::allocation_count();
  EXPECT_EQ(after - before, 0);
  EXPECT_TRUE(std::isfinite(sum));
  auto* probe = new int(3);  // the counter works
  EXPECT_EQ(tutti::test::allocation_count(), after + 1);
  delete probe;
}

}  // namespace
}  // namespace tutti::ensemble_variation
