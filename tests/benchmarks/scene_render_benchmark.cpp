// SPDX-License-Identifier: MIT
// Milliseconds per frame of the two demo scenes at 1280x720, 1x and 4x MSAA, on the Vulkan device
// (lavapipe on a machine without a GPU): posing only, posing + rendering + readback, and all of
// that + H.264 encoding through ffmpeg (what `tutti render -o OUT.mp4` does per frame). Frames
// step at 30 fps through the scene so the systems and the camera cuts do real work.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <tutti/cli/video_pipe.hpp>
#include <tutti/render/model_renderer.hpp>
#include <tutti/render/offscreen_target.hpp>
#include <tutti/render/vulkan_context.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/runtime/stage_view.hpp>
#include <tutti/stage/stage.hpp>

namespace {

constexpr std::uint32_t kWidth = 1280;
constexpr std::uint32_t kHeight = 720;
constexpr int kFps = 30;

struct Fixture {
  std::unique_ptr<tutti::stage::Stage> stage;
  std::unique_ptr<tutti::render::VulkanContext> context;
  std::unique_ptr<tutti::render::OffscreenTarget> target;
  std::unique_ptr<tutti::render::ModelRenderer> renderer;
  std::vector<const tutti::model::ModelAsset*> models;
};

std::unique_ptr<Fixture> make_fixture(benchmark::State& state, const char* scene_name,
                                      VkSampleCountFlagBits samples) {
  auto scene = tutti::scene::load_scene(std::filesystem::path(TUTTI_SOURCE_DIR) / "content" /
                                        "scenes" / scene_name,
                                        tutti::performance::scene_load_options());
  if (!scene) {
    state.SkipWithError(scene.error().message.c_str());
    return nullptr;
  }
  auto fixture = std::make_unique<Fixture>();
  auto stage = tutti::performance::build_stage(*scene, {});
  if (!stage) {
    state.SkipWithError(stage.error().message.c_str());
    return nullptr;
  }
  fixture->stage = std::move(*stage);
  auto context = tutti::render::VulkanContext::create({});
  if (!context) {
    state.SkipWithError(context.error().message.c_str());
    return nullptr;
  }
  fixture->context = std::move(*context);
  auto target =
      tutti::render::OffscreenTarget::create(*fixture->context, kWidth, kHeight, 2, samples);
  if (!target) {
    state.SkipWithError(target.error().message.c_str());
    return nullptr;
  }
  fixture->target = std::move(*target);
  fixture->models = fixture->stage->model_list();
  auto renderer =
      tutti::render::ModelRenderer::create(*fixture->context, *fixture->target, fixture->models);
  if (!renderer) {
    state.SkipWithError(renderer.error().message.c_str());
    return nullptr;
  }
  fixture->renderer = std::move(*renderer);
  return fixture;
}

enum class Work { pose, render, encode };

void run_frames(benchmark::State& state, const char* scene_name, Work work) {
  const auto samples = static_cast<VkSampleCountFlagBits>(state.range(0));
  auto fixture = make_fixture(state, scene_name, samples);
  if (!fixture) return;
  tutti::stage::Stage& stage = *fixture->stage;
  std::unique_ptr<tutti::cli::VideoPipe> video;
  const std::filesystem::path video_path =
      std::filesystem::temp_directory_path() / "tutti_scene_render_benchmark.mp4";
  if (work == Work::encode) {
    auto opened = tutti::cli::VideoPipe::open(video_path, kWidth, kHeight, kFps);
    if (!opened) {
      state.SkipWithError(opened.error().message.c_str());
      return;
    }
    video = std::move(*opened);
  }
  const tutti::render::Lighting lighting = tutti::runtime::lighting_of(stage);
  std::vector<tutti::render::ModelInstance> instances;
  std::vector<std::uint8_t> rgba;
  const double span = stage.end_s() - stage.start_s();
  std::int64_t frame = 0;
  for (auto _ : state) {
    const double t = stage.start_s() + std::fmod(static_cast<double>(frame++) / kFps, span);
    tutti::stage::evaluate_stage(stage, t);
    tutti::runtime::collect_instances(stage, instances);
    if (work == Work::pose) {
      benchmark::DoNotOptimize(instances.data());
      continue;
    }
    auto recording = fixture->target->begin_frame();
    if (!recording) {
      state.SkipWithError(recording.error().message.c_str());
      return;
    }
    tutti::Status s = fixture->renderer->record(
        *recording, *fixture->target, instances,
        tutti::runtime::camera_at(stage, t, static_cast<float>(kWidth) / kHeight), lighting,
        {0.02f, 0.02f, 0.03f, 1.0f});
    auto id = fixture->target->end_frame();
    if (!s || !id || !fixture->target->read_pixels(*id, rgba)) {
      state.SkipWithError("rendering failed");
      return;
    }
    if (video && !video->write(rgba)) {
      state.SkipWithError("ffmpeg failed");
      return;
    }
  }
  if (video) (void)video->finish();
  std::error_code ignored;
  std::filesystem::remove(video_path, ignored);
  if (work != Work::pose) {
    const tutti::render::RenderStats& stats = fixture->renderer->last_stats();
    state.counters["main_tris"] = static_cast<double>(stats.main_triangles);
    state.counters["shadow_tris"] = static_cast<double>(stats.shadow_triangles);
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_PianoPose(benchmark::State& state) { run_frames(state, "piano.json", Work::pose); }
void BM_PianoRender(benchmark::State& state) { run_frames(state, "piano.json", Work::render); }
void BM_PianoRenderEncode(benchmark::State& state) {
  run_frames(state, "piano.json", Work::encode);
}
void BM_QuartetPose(benchmark::State& state) { run_frames(state, "quartet.json", Work::pose); }
void BM_QuartetRender(benchmark::State& state) { run_frames(state, "quartet.json", Work::render); }
void BM_QuartetRenderEncode(benchmark::State& state) {
  run_frames(state, "quartet.json", Work::encode);
}

BENCHMARK(BM_PianoPose)->ArgName("msaa")->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_QuartetPose)->ArgName("msaa")->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PianoRender)
    ->ArgName("msaa")
    ->Arg(1)
    ->Arg(4)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(90)
    ->UseRealTime();
BENCHMARK(BM_PianoRenderEncode)
    ->ArgName("msaa")
    ->Arg(1)
    ->Arg(4)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(90)
    ->UseRealTime();
BENCHMARK(BM_QuartetRender)
    ->ArgName("msaa")
    ->Arg(1)
    ->Arg(4)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(90)
    ->UseRealTime();
BENCHMARK(BM_QuartetRenderEncode)
    ->ArgName("msaa")
    ->Arg(1)
    ->Arg(4)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(90)
    ->UseRealTime();

}  // namespace
