// SPDX-License-Identifier: MIT
// Brass planning throughput: a long trumpet line and a long trombone line (slide timing), one
// core, notes per second.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

#include <tutti/brass_model/instrument.hpp>
#include <tutti/brass_motion/evaluate_brass_pose.hpp>
#include <tutti/brass_motion/plan_brass_motion.hpp>
#include <tutti/fingering_planner/brass_planner.hpp>

namespace {

using namespace tutti::fingering_planner;
using namespace tutti::brass_model;
using namespace tutti::brass_motion;

const Instrument& instrument(const std::string& id) {
  static const std::vector<Instrument> all = *load_all_instruments();
  for (const Instrument& i : all) {
    if (i.id == id) return i;
  }
  return all.front();
}

// A deterministic melody over an octave and a half of the instrument's middle register.
BrassLine melody(const Instrument& on, int count) {
  BrassLine line;
  line.instrument = &on;
  const int low = on.sounding(on.lowest_written) + 7;
  unsigned state = 12345;
  int key = low + 9;
  for (int i = 0; i < count; ++i) {
    state = state * 1103515245u + 12345u;
    const int step = static_cast<int>((state >> 16) % 9) - 4;
    key = std::clamp(key + step, low, low + 19);
    LineNote n;
    n.onset_s = i * 0.15;
    n.offset_s = n.onset_s + 0.14;
    n.onset_beats = n.onset_s * 2.0;
    n.offset_beats = n.offset_s * 2.0;
    n.sounding = key;
    n.written = on.written(key);
    line.notes.push_back(n);
  }
  return line;
}

void run(benchmark::State& state, const char* id) {
  const PlannerWeights weights = *load_planner_weights();
  BrassLine line = melody(instrument(id), static_cast<int>(state.range(0)));
  for (auto _ : state) {
    BrassPlanSummary summary = plan_line(line, weights);
    benchmark::DoNotOptimize(summary);
  }
  state.counters["notes/s"] = benchmark::Counter(
      static_cast<double>(state.iterations() * line.notes.size()), benchmark::Counter::kIsRate);
}

void BM_BrassTrumpetLine(benchmark::State& state) { run(state, "trumpet_bb"); }
void BM_BrassTromboneLine(benchmark::State& state) { run(state, "trombone_tenor"); }
BENCHMARK(BM_BrassTrumpetLine)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BrassTromboneLine)->Arg(100000)->Unit(benchmark::kMillisecond);

// The pose of a trombone player (valves, slide, embouchure) at random times of a long line.
void BM_EvaluateBrassPose(benchmark::State& state) {
  const PlannerWeights weights = *load_planner_weights();
  BrassLine line = melody(instrument("trombone_tenor"), 100000);
  plan_line(line, weights);
  const BrassMotionPlan plan = plan_brass_motion(line, *load_brass_motion_params(), weights.change);
  const double end = line.notes.back().offset_s;
  unsigned seed = 7;
  double sink = 0.0;
  for (auto _ : state) {
    seed = seed * 1103515245u + 12345u;
    const BrassPose pose = evaluate_brass_pose(plan, end * ((seed >> 8) & 0xffff) / 65536.0);
    sink += pose.slide_mm;
  }
  benchmark::DoNotOptimize(sink);
}
BENCHMARK(BM_EvaluateBrassPose);

}  // namespace
