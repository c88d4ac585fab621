// SPDX-License-Identifier: MIT
// evaluate_brass_pose and evaluate_breath never allocate: this program replaces the global
// operator new with a counting one and evaluates many frames after planning.
#include <gtest/gtest.h>

#include <cmath>

#include "allocation_counter.hpp"
#include <tutti/brass_motion/evaluate_brass_pose.hpp>
#include <tutti/brass_motion/plan_brass_motion.hpp>
#include <tutti/fingering_planner/brass_planner.hpp>

namespace tutti::brass_motion {

// The brass planner's names used here (systems/fingering_planner).
using fingering_planner::load_planner_weights;
using fingering_planner::plan_line;

// The brass model's names used here (systems/brass_model).
using brass_model::BrassLine;
using brass_model::Instrument;
using brass_model::LineNote;
using brass_model::load_all_instruments;

namespace {

TEST(BrassPoseAllocation, NoAllocationPerEvaluation) {
  auto instruments = load_all_instruments();
  ASSERT_TRUE(instruments.ok()) << instruments.error().message;
  auto weights = load_planner_weights();
  auto params = load_brass_motion_params();
  ASSERT_TRUE(weights.ok() && params.ok());
  for (const Instrument& instrument : *instruments) {
    BrassLine line;
    line.instrument = &instrument;
    const int low = instrument.sounding(instrument.lowest_written);
    for (int i = 0; i < 64; ++i) {
      LineNote n;
      n.onset_s = 0.25 * i;
      n.offset_s = n.onset_s + 0.2;
      n.sounding = low + 5 + (i * 5) % 19;
      n.written = instrument.written(n.sounding);
      line.notes.push_back(n);
    }
    plan_line(line, *weights);
    const BrassMotionPlan plan = plan_brass_motion(line, *params, weights->change);
    double sink = 0.0;
    const long before = tutti::test::allocation_count();
    for (int k = 0; k < 20000; ++k) {
      const BrassPose pose = evaluate_brass_pose(plan, -1.0 + k * 0.001);
      sink += pose.slide_mm + pose.tension + pose.valve_press[0];
    }
    EXPECT_EQ(tutti::test::allocation_count() - before, 0) << instrument.id;
    EXPECT_TRUE(std::isfinite(sink));
  }
}

}  // namespace
}  // namespace tutti::brass_motion
