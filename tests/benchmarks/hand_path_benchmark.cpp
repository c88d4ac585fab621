// SPDX-License-Identifier: MIT
// Hand path planning (taut string + smoothing) and evaluation at scale. Items are corridors
// (planning) or evaluate() calls.

#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <vector>

#include <tutti/piano_model/hand_corridor.hpp>
#include <tutti/spline_motion/corridor_portals.hpp>
#include <tutti/spline_motion/smoothing.hpp>
#include <tutti/spline_motion/taut_string.hpp>

namespace {

using tutti::piano_model::HandCorridor;
using tutti::piano_model::HandCorridors;
using tutti::spline_motion::HandPath;
using tutti::spline_motion::PlanOptions;
using tutti::spline_motion::SmoothingMode;

// Piano-like: notes of 20..500 ms, legato (touching) or detached, steps and leaps.
HandCorridors make_corridors(int count, std::uint64_t seed = 1) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  HandCorridors out;
  out.reserve(static_cast<std::size_t>(count));
  double t = 0.0;
  double centre = 600.0;
  for (int i = 0; i < count; ++i) {
    const double width = 40.0 * unit(rng);
    centre += (unit(rng) < 0.15 ? 300.0 : 40.0) * (2.0 * unit(rng) - 1.0);
    centre = centre < 0.0 ? 0.0 : centre > 1300.0 ? 1300.0 : centre;
    if (i > 0) t += unit(rng) < 0.3 ? 0.005 : 0.1 * unit(rng);
    const double duration = 0.02 + 0.48 * unit(rng);
    out.push_back({t, t + duration, centre - width / 2, centre + width / 2});
    t += duration;
  }
  return out;
}

void BM_TautString(benchmark::State& state) {
  const HandCorridors corridors = make_corridors(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    auto s = tutti::spline_motion::taut_string(corridors);
    benchmark::DoNotOptimize(s.ok());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_TautString)->Arg(1'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void BM_PlanHandPath(benchmark::State& state) {
  const HandCorridors corridors = make_corridors(static_cast<int>(state.range(0)));
  const PlanOptions options{static_cast<SmoothingMode>(state.range(1))};
  for (auto _ : state) {
    auto path = tutti::spline_motion::plan_hand_path(corridors, options);
    benchmark::DoNotOptimize(path.ok());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.SetLabel(tutti::spline_motion::to_string(options.smoothing));
}
BENCHMARK(BM_PlanHandPath)
    ->Args({1'000, static_cast<int>(SmoothingMode::monotone_quintic)})
    ->Args({1'000'000, static_cast<int>(SmoothingMode::monotone_quintic)})
    ->Args({1'000'000, static_cast<int>(SmoothingMode::pchip)})
    ->Args({1'000'000, static_cast<int>(SmoothingMode::natural_spline)})
    ->Unit(benchmark::kMillisecond);

// Random times (cache-cold binary search on big paths) and sequential frames (60 fps playback).
void BM_EvaluateRandom(benchmark::State& state) {
  const HandCorridors corridors = make_corridors(static_cast<int>(state.range(0)));
  const HandPath path = tutti::spline_motion::plan_hand_path(corridors).value();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(path.start_s(), path.end_s());
  std::vector<double> times(4096);
  for (double& t : times) t = u(rng);
  std::size_t i = 0;
  for (auto _ : state) {
    const auto s = tutti::spline_motion::evaluate(path, times[i++ & 4095]);
    benchmark::DoNotOptimize(s);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EvaluateRandom)->Arg(1'000)->Arg(1'000'000);

void BM_EvaluateFrames(benchmark::State& state) {
  const HandCorridors corridors = make_corridors(static_cast<int>(state.range(0)));
  const HandPath path = tutti::spline_motion::plan_hand_path(corridors).value();
  double t = path.start_s();
  for (auto _ : state) {
    const auto s = tutti::spline_motion::evaluate(path, t);
    benchmark::DoNotOptimize(s);
    t += 1.0 / 60.0;
    if (t > path.end_s()) t = path.start_s();
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EvaluateFrames)->Arg(1'000'000);

}  // namespace
