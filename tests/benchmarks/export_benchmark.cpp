// SPDX-License-Identifier: MIT
// What `tutti export` costs: posing the stage at every frame, reducing the keys and writing the
// .glb, for ten seconds of each demo scene at 30 fps; and the reduction alone on a long smooth
// channel. Counters: exported frames per second of export time, output bytes.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

#include <tutti/export/keyframe_reduction.hpp>
#include <tutti/export/scene_export.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/scene/load_scene.hpp>

namespace {

using namespace tutti;

stage::Stage* staged(const char* scene_name) {
  auto scene = scene::load_scene(std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes" /
                                 scene_name, performance::scene_load_options());
  if (!scene) return nullptr;
  auto stage = performance::build_stage(*scene, {});
  return stage ? stage->release() : nullptr;
}

void export_scene(benchmark::State& state, const char* scene_name) {
  static stage::Stage* piano = staged("piano.json");
  static stage::Stage* quartet = staged("quartet.json");
  stage::Stage* stage = std::string_view(scene_name) == "piano.json" ? piano : quartet;
  if (stage == nullptr) {
    state.SkipWithError("the scene did not build");
    return;
  }
  const gltf_export::ExportRange range{30, 0, 300};
  std::size_t bytes = 0;
  for (auto _ : state) {
    auto exported = gltf_export::export_performance(*stage, range);
    if (!exported) {
      state.SkipWithError(exported.error().message.c_str());
      return;
    }
    bytes = exported->glb.size();
    benchmark::DoNotOptimize(exported->glb.data());
  }
  state.counters["frames/s"] = benchmark::Counter(static_cast<double>(range.frame_count),
                                                  benchmark::Counter::kIsIterationInvariantRate);
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK_CAPTURE(export_scene, piano_10s, "piano.json")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(export_scene, quartet_10s, "quartet.json")->Unit(benchmark::kMillisecond);

void reduce_rotation_channel(benchmark::State& state) {
  std::vector<glm::quat> samples;
  for (int k = 0; k < 1800; ++k) {  // one minute at 30 fps
    const float t = static_cast<float>(k) / 30.0f;
    samples.push_back(glm::angleAxis(0.5f * std::sin(2.0f * t), glm::vec3(1, 0, 0)) *
                      glm::angleAxis(0.3f * std::sin(0.7f * t), glm::vec3(0, 1, 0)));
  }
  std::size_t keys = 0;
  for (auto _ : state) {
    keys = gltf_export::reduce_rotation(samples, 1.745329e-4f, 256).size();
    benchmark::DoNotOptimize(keys);
  }
  state.counters["keys"] = static_cast<double>(keys);
  state.counters["samples/s"] = benchmark::Counter(static_cast<double>(samples.size()),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(reduce_rotation_channel)->Unit(benchmark::kMicrosecond);

}  // namespace
