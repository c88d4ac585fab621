// SPDX-License-Identifier: MIT
// tutti_render_bench [--device SEL] [--frames N] [--size WxH]: times clear + one triangle +
// readback per frame on the chosen device, first one frame at a time (render, wait, read), then
// pipelined through the 2-frame ring (frame k is read while k+1 renders). Prints ms per frame.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <tutti/render/color_mesh_pipeline.hpp>
#include <tutti/render/offscreen_target.hpp>
#include <tutti/render/vulkan_context.hpp>

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

int fail(const tutti::Error& error) {
  std::fprintf(stderr, "error: %s\n", error.message.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tutti::render;
  VulkanContextOptions options;
  int frames = 30;
  std::uint32_t width = 1280;
  std::uint32_t height = 720;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--device") {
      options.device = argv[i + 1];
    } else if (flag == "--frames") {
      frames = std::max(1, std::atoi(argv[i + 1]));
    } else if (flag == "--size") {
      if (std::sscanf(argv[i + 1], "%ux%u", &width, &height) != 2) return 2;
    } else {
      std::fprintf(stderr, "usage: %s [--device SEL] [--frames N] [--size WxH]\n", argv[0]);
      return 2;
    }
  }

  auto context = VulkanContext::create(options);
  if (!context) return fail(context.error());
  auto target = OffscreenTarget::create(**context, width, height, 2);
  if (!target) return fail(target.error());
  auto pipeline =
      ColorMeshPipeline::create(**context, (*target)->color_format(), (*target)->depth_format());
  if (!pipeline) return fail(pipeline.error());
  const ColorVertex vertices[] = {{{0.0f, -0.8f, 0.5f}, {1.0f, 0.2f, 0.1f}},
                                  {{0.8f, 0.8f, 0.5f}, {0.1f, 1.0f, 0.2f}},
                                  {{-0.8f, 0.8f, 0.5f}, {0.1f, 0.2f, 1.0f}}};
  auto mesh = ColorMesh::create(**context, vertices);
  if (!mesh) return fail(mesh.error());

  std::vector<std::uint8_t> pixels;
  auto render = [&]() -> tutti::Result<std::uint64_t> {
    auto frame = (*target)->begin_frame({0.05f, 0.05f, 0.08f, 1.0f});
    if (!frame) return frame.error();
    (*pipeline)->draw(frame->commands, *mesh, glm::mat4(1.0f));
    return (*target)->end_frame();
  };

  // Warm-up: the first frame compiles the pipeline's shaders in lavapipe.
  auto warm = render();
  if (!warm) return fail(warm.error());
  if (auto s = (*target)->read_pixels(*warm, pixels); !s) return fail(s.error());

  std::vector<double> serial_ms;
  for (int i = 0; i < frames; ++i) {
    const auto start = Clock::now();
    auto id = render();
    if (!id) return fail(id.error());
    if (auto s = (*target)->read_pixels(*id, pixels); !s) return fail(s.error());
    serial_ms.push_back(ms_since(start));
  }
  std::sort(serial_ms.begin(), serial_ms.end());

  const auto pipelined_start = Clock::now();
  std::uint64_t previous = 0;
  for (int i = 0; i < frames; ++i) {
    auto id = render();
    if (!id) return fail(id.error());
    if (previous != 0) {
      if (auto s = (*target)->read_pixels(previous, pixels); !s) return fail(s.error());
    }
    previous = *id;
  }
  if (auto s = (*target)->read_pixels(previous, pixels); !s) return fail(s.error());
  const double pipelined_ms = ms_since(pipelined_start) / frames;

  std::printf("device: %s (%s)\n", (*context)->device_info().name.c_str(),
              device_type_name((*context)->device_info().type));
  std::printf(
      "%ux%u clear+triangle+readback, %d frames: serial median %.2f ms (min %.2f, max "
      "%.2f), pipelined %.2f ms/frame\n",
      width, height, frames, serial_ms[serial_ms.size() / 2], serial_ms.front(), serial_ms.back(),
      pipelined_ms);
  return 0;
}
