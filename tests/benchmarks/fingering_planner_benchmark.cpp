// SPDX-License-Identifier: MIT
// Exact planner throughput: a long single-line melody, and two-hand chordal music.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include <tutti/fingering_planner/exact_planner.hpp>
#include <tutti/fingering_planner/local_replan.hpp>

namespace {

using namespace tutti::fingering_planner;

const FingeringModel& model() {
  static const FingeringModel m = *load_fingering_model("default");
  return m;
}

// Deterministic pseudo-random walk over a C-major-ish range.
std::vector<PlanNote> melody(int count, int base) {
  std::vector<PlanNote> notes;
  unsigned state = 12345;
  int key = base;
  for (int i = 0; i < count; ++i) {
    state = state * 1103515245u + 12345u;
    const int step = static_cast<int>((state >> 16) % 7) - 3;
    key = std::clamp(key + step, base - 10, base + 14);
    notes.push_back({key, i * 0.125, (i + 1) * 0.125, 0});
  }
  return notes;
}

// Three-note chords alternating with single notes, as in an accompaniment.
std::vector<PlanNote> chords(int events, int base) {
  std::vector<PlanNote> notes;
  const int shapes[4][3] = {{0, 4, 7}, {2, 5, 9}, {-1, 2, 7}, {0, 4, 9}};
  for (int e = 0; e < events; ++e) {
    const auto& s = shapes[e % 4];
    const double t = e * 0.25;
    if (e % 2 == 0) {
      for (int k : s) notes.push_back({base + k, t, t + 0.25, 0});
    } else {
      notes.push_back({base + s[1], t, t + 0.25, 0});
    }
  }
  return notes;
}

void BM_ExactMelody(benchmark::State& state) {
  const auto notes = melody(static_cast<int>(state.range(0)), 67);
  for (auto _ : state) {
    auto plan = plan_hand_exact(notes, tutti::music::Hand::right, model());
    benchmark::DoNotOptimize(plan);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(notes.size()));
  state.counters["notes/s"] = benchmark::Counter(
      static_cast<double>(state.iterations() * notes.size()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ExactMelody)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_ExactTwoHandChords(benchmark::State& state) {
  const auto right = chords(static_cast<int>(state.range(0)), 67);
  const auto left = chords(static_cast<int>(state.range(0)), 48);
  for (auto _ : state) {
    auto r = plan_hand_exact(right, tutti::music::Hand::right, model());
    auto l = plan_hand_exact(left, tutti::music::Hand::left, model());
    benchmark::DoNotOptimize(r);
    benchmark::DoNotOptimize(l);
  }
  const auto total = static_cast<double>(right.size() + left.size());
  state.counters["notes/s"] = benchmark::Counter(static_cast<double>(state.iterations()) * total,
                                                 benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ExactTwoHandChords)->Arg(50000)->Unit(benchmark::kMillisecond);

// One finger pinned in the middle of a long melody (an editor click): the local re-plan.
void BM_LocalReplanAfterPin(benchmark::State& state) {
  auto notes = melody(static_cast<int>(state.range(0)), 67);
  const auto plan = *plan_hand_exact(notes, tutti::music::Hand::right, model());
  const int index = static_cast<int>(notes.size() / 2);
  notes[static_cast<std::size_t>(index)].pin =
      plan.fingers[static_cast<std::size_t>(index)] % 5 + 1;
  const int edited[] = {index};
  int searched = 0;
  for (auto _ : state) {
    auto replan = replan_hand_locally(notes, tutti::music::Hand::right, model(), plan, edited);
    searched = replan->searched_last_event - replan->searched_first_event + 1;
    benchmark::DoNotOptimize(replan);
  }
  state.counters["searched_events"] = searched;
}
BENCHMARK(BM_LocalReplanAfterPin)->Arg(1000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
