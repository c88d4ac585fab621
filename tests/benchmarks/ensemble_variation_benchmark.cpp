// SPDX-License-Identifier: MIT
// Ensemble body motion (systems/ensemble_variation) for a 10-minute part at 120 BPM in 4/4 with a
// breath every 4 bars: planning one player, and evaluate_body_motion at random times (the cost a
// frame pays per player).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include <tutti/ensemble_variation/ensemble_plan.hpp>
#include <tutti/ensemble_variation/evaluate_body_motion.hpp>

namespace {

using namespace tutti;

struct Fixture {
  music::Score score;
  std::vector<ensemble_variation::BreathInput> breaths;
  std::vector<ensemble_variation::PerformerInput> inputs;
};

Fixture make_fixture() {
  Fixture f;
  music::TimeSignature ts;
  f.score.time_signatures.push_back(ts);
  for (double t = 7.0; t < 600.0; t += 8.0) {
    ensemble_variation::BreathInput e;
    e.prepare_start_s = t;
    e.start_s = t + 0.3;
    e.end_s = t + 0.9;
    f.breaths.push_back(e);
  }
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    ensemble_variation::PerformerInput in;
    in.seed = seed;
    in.params = ensemble_variation::draw_variation(seed);
    in.lead = seed == 1;
    in.score = &f.score;
    in.breaths = f.breaths;
    in.first_onset_s = 1.0;
    in.last_offset_s = 600.0;
    f.inputs.push_back(in);
  }
  return f;
}

void BM_PlanQuartet(benchmark::State& state) {
  const Fixture f = make_fixture();
  for (auto _ : state) {
    auto plan = ensemble_variation::plan_ensemble(f.inputs);
    benchmark::DoNotOptimize(plan);
  }
}

void BM_EvaluateBodyMotion(benchmark::State& state) {
  const Fixture f = make_fixture();
  const auto plan = ensemble_variation::plan_ensemble(f.inputs);
  std::uint64_t x = 12345;
  for (auto _ : state) {
    x = x * 6364136223846793005ull + 1442695040888963407ull;
    const double t = static_cast<double>(x >> 11) * 0x1.0p-53 * 600.0;
    benchmark::DoNotOptimize(ensemble_variation::evaluate_body_motion(plan->performers[0], t));
  }
}

BENCHMARK(BM_PlanQuartet)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EvaluateBodyMotion)->Unit(benchmark::kNanosecond);

}  // namespace
