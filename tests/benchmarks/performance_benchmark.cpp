// SPDX-License-Identifier: MIT
// What a host pays for tutti::performance: sample(t) — the whole frame (sync, evaluate, express,
// pose) and every model's node transforms and morph weights copied out — per 60 fps frame of
// each demo scene, over the first 10 s; the same in a context of each thread's own over one
// shared plan (1 and 2 threads: this machine has 2 cores); and opening a scene (load, plan,
// stage, find the events and contacts).
// The budget: 5 % of a 60 fps frame, 833 µs.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <tutti/performance/performance.hpp>

namespace {

using namespace tutti;

std::filesystem::path scene_file(const char* name) {
  return std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes" / name;
}

void sample_scene(benchmark::State& state, const char* name) {
  auto opened = performance::Performance::open(scene_file(name));
  if (!opened) {
    state.SkipWithError(opened.error().message.c_str());
    return;
  }
  performance::Performance& p = **opened;
  performance::Sample sample;
  std::size_t nodes = 0;
  p.sample(p.start_s(), sample);
  for (const performance::ModelPose& model : sample.models) nodes += model.local.size();
  std::int64_t frame = 0;
  for (auto _ : state) {
    p.sample(p.start_s() + static_cast<double>(frame % 600) / 60.0, sample);
    benchmark::DoNotOptimize(sample.models.data());
    ++frame;
  }
  state.counters["models"] = static_cast<double>(sample.models.size());
  state.counters["nodes"] = static_cast<double>(nodes);
  state.counters["frames_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                      benchmark::Counter::kIsRate);
}

// One performance per scene, opened once and shared by the benchmark's threads.
const performance::Performance* shared_performance(const char* name) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<performance::Performance>> opened;
  const std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<performance::Performance>& p = opened[name];
  if (!p) {
    auto result = performance::Performance::open(scene_file(name));
    if (result) p = std::move(*result);
  }
  return p.get();
}

// Each thread samples the one shared plan in its own context (sample(context, t, out)).
void sample_in_context(benchmark::State& state, const char* name) {
  const performance::Performance* p = shared_performance(name);
  if (p == nullptr) {
    state.SkipWithError("the scene did not open");
    return;
  }
  performance::SampleContext context = p->make_context();
  performance::Sample sample;
  std::int64_t frame = state.thread_index() * 150;
  for (auto _ : state) {
    p->sample(context, p->start_s() + static_cast<double>(frame % 600) / 60.0, sample);
    benchmark::DoNotOptimize(sample.models.data());
    ++frame;
  }
  state.counters["frames_per_s"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                      benchmark::Counter::kIsRate);
}

void open_scene(benchmark::State& state, const char* name, double contact_step_s) {
  performance::Options options;
  options.contact_step_s = contact_step_s;
  std::size_t events = 0;
  for (auto _ : state) {
    auto opened = performance::Performance::open(scene_file(name), options);
    if (!opened) {
      state.SkipWithError(opened.error().message.c_str());
      return;
    }
    events = (*opened)->events().size();
  }
  state.counters["events"] = static_cast<double>(events);
}

BENCHMARK_CAPTURE(sample_scene, quartet, "quartet.json")->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(sample_scene, quintet, "quintet.json")->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(sample_scene, piano, "piano.json")->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(sample_in_context, quartet, "quartet.json")
    ->Unit(benchmark::kMicrosecond)
    ->Threads(1)
    ->Threads(2)
    ->UseRealTime();
BENCHMARK_CAPTURE(sample_in_context, quintet, "quintet.json")
    ->Unit(benchmark::kMicrosecond)
    ->Threads(1)
    ->Threads(2)
    ->UseRealTime();
BENCHMARK_CAPTURE(open_scene, quartet, "quartet.json", 0.001)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(open_scene, quartet_no_contacts, "quartet.json", 0.0)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(open_scene, piano, "piano.json", 0.001)->Unit(benchmark::kMillisecond);

}  // namespace
