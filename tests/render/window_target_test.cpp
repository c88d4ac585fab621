// SPDX-License-Identifier: MIT
// WindowTarget smoke test: a real window on an X server (ctest runs this program under
// `xvfb-run`, a virtual one). Without a display the window tests print "SKIPPED: no display" and
// skip; without a Vulkan device, "SKIPPED: no Vulkan device". Validation (with synchronization
// validation) is on and any message fails the test.
#include <tutti/render/window_target.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <tutti/image/png.hpp>
#include <tutti/render/color_mesh_pipeline.hpp>
#include <tutti/render/vulkan_context.hpp>
#include <tutti/render/window.hpp>
#include "render_test_support.hpp"
#ifdef TUTTI_TEST_X11_PIXELS
#include "x11_window_pixels.hpp"
#endif

namespace tutti::render {
namespace {

using test::pixel_near;
using test::pixel_string;
using test::Rgb;
using test::srgb;

constexpr float kTriangle[3] = {0.9f, 0.2f, 0.1f};  // linear RGB, every vertex

bool is_no_display_error(const Error& error) {
  return error.message.rfind("cannot open a window: no display", 0) == 0;
}

// Skipped only when there is no display at all; a DISPLAY that cannot be opened is a failure.
bool have_display() {
  const char* display = std::getenv("DISPLAY");
  return display != nullptr && display[0] != '\0';
}

// A triangle around the origin in clip space (the MVP rotates it about z); the centre of the
// window stays inside it at every angle.
std::vector<ColorVertex> triangle() {
  const glm::vec3 c(kTriangle[0], kTriangle[1], kTriangle[2]);
  return {{{0.0f, -0.7f, 0.5f}, c}, {{-0.6f, 0.5f, 0.5f}, c}, {{0.6f, 0.5f, 0.5f}, c}};
}

glm::mat4 rotation_z(float radians) {
  glm::mat4 m(1.0f);
  m[0][0] = std::cos(radians);
  m[0][1] = std::sin(radians);
  m[1][0] = -std::sin(radians);
  m[1][1] = std::cos(radians);
  return m;
}

ClearColor animated_clear(int frame) {
  const float t = static_cast<float>(frame) / 30.0f;
  return {0.05f + 0.05f * std::sin(t), 0.1f, 0.3f + 0.1f * std::cos(t), 1.0f};
}

Rgb srgb_of(const ClearColor& c) { return srgb(c.r, c.g, c.b); }

bool near(const std::vector<std::uint8_t>& rgba, std::size_t i, Rgb want, int tolerance) {
  return std::abs(rgba[i] - want.r) <= tolerance && std::abs(rgba[i + 1] - want.g) <= tolerance &&
         std::abs(rgba[i + 2] - want.b) <= tolerance;
}

// Pixels that are neither the clear colour nor the triangle's: MSAA-blended edges.
std::size_t blended_pixels(const CapturedFrame& frame, Rgb clear) {
  const Rgb tri = srgb(kTriangle[0], kTriangle[1], kTriangle[2]);
  std::size_t count = 0;
  for (std::size_t i = 0; i < frame.rgba.size(); i += 4) {
    if (!near(frame.rgba, i, clear, 3) && !near(frame.rgba, i, tri, 3)) ++count;
  }
  return count;
}

void keep_artifact(const CapturedFrame& frame, const std::string& name) {
  const std::filesystem::path dir = TUTTI_RENDER_ARTIFACT_DIR;
  std::error_code ignored;
  std::filesystem::create_directories(dir, ignored);
  Status written = image::write_png(dir / name, frame.rgba, frame.width, frame.height);
  EXPECT_TRUE(written) << written.error().message;
}

class WindowTargetTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!have_display()) {
      std::printf("SKIPPED: no display\n");
      GTEST_SKIP() << "DISPLAY is not set";
    }
    auto window = Window::create({.width = 640, .height = 360, .title = "tutti window test"});
    ASSERT_TRUE(window) << window.error().message;
    window_ = std::move(*window);

    VulkanContextOptions options;
    options.validation = true;
    options.synchronization_validation = true;
    require_presentation(*window_, options);
    auto context = VulkanContext::create(options);
    if (!context && test::is_no_device_error(context.error())) {
      std::printf("SKIPPED: no Vulkan device\n");
      GTEST_SKIP() << context.error().message;
    }
    ASSERT_TRUE(context) << context.error().message;
    context_ = std::move(*context);
    log_ = context_->validation_log();
  }

  void TearDown() override {
    // Frames may still be in flight using the pipeline and the mesh.
    if (context_ != nullptr) {
      EXPECT_TRUE(context_->wait_idle());
    }
    pipeline_.reset();
    mesh_.reset();
    target_.reset();
    context_.reset();
    window_.reset();
    if (log_ == nullptr) return;
    const std::vector<std::string> messages = log_->messages();
    for (const std::string& message : messages) std::printf("%s\n", message.c_str());
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s), printed above";
  }

  // Target, pipeline (for the target's sample count) and the triangle.
  void make_target(VkSampleCountFlagBits samples) {
    auto target = WindowTarget::create(*context_, *window_, {.samples = samples});
    ASSERT_TRUE(target) << target.error().message;
    target_ = std::move(*target);
    auto pipeline = ColorMeshPipeline::create(*context_, target_->color_format(),
                                              target_->depth_format(), target_->samples());
    ASSERT_TRUE(pipeline) << pipeline.error().message;
    pipeline_ = std::move(*pipeline);
    const std::vector<ColorVertex> vertices = triangle();
    auto mesh = ColorMesh::create(*context_, vertices);
    ASSERT_TRUE(mesh) << mesh.error().message;
    mesh_.emplace(std::move(*mesh));
  }

  // One frame: animated clear, the triangle turned by `frame`; optionally captured.
  void render(int frame, bool capture) {
    window_->poll_events();
    if (capture) target_->capture_next_frame();
    auto recording = target_->begin_frame();
    ASSERT_TRUE(recording) << "frame " << frame << ": " << recording.error().message;
    target_->begin_main_pass(animated_clear(frame));
    pipeline_->draw(recording->commands, *mesh_, rotation_z(0.02f * static_cast<float>(frame)));
    auto id = target_->end_frame();
    ASSERT_TRUE(id) << "frame " << frame << ": " << id.error().message;
    EXPECT_EQ(*id, recording->id);
  }

  std::unique_ptr<Window> window_;
  std::unique_ptr<VulkanContext> context_;
  std::shared_ptr<const ValidationLog> log_;
  std::unique_ptr<WindowTarget> target_;
  std::unique_ptr<ColorMeshPipeline> pipeline_;
  std::optional<ColorMesh> mesh_;
};

// Clear colour in the corner, triangle colour in the centre, RGBA8 of the frame's size.
void expect_frame(const CapturedFrame& frame, VkExtent2D extent, const ClearColor& clear) {
  ASSERT_EQ(frame.width, extent.width);
  ASSERT_EQ(frame.height, extent.height);
  ASSERT_EQ(frame.rgba.size(), std::size_t{extent.width} * extent.height * 4);
  EXPECT_TRUE(pixel_near(frame.rgba, frame.width, 2, 2, srgb_of(clear)));
  EXPECT_TRUE(
      pixel_near(frame.rgba, frame.width, frame.width - 3, frame.height - 3, srgb_of(clear)));
  EXPECT_TRUE(pixel_near(frame.rgba, frame.width, frame.width / 2, frame.height / 2,
                         srgb(kTriangle[0], kTriangle[1], kTriangle[2])));
}

TEST_F(WindowTargetTest, PresentsAnimatedMsaaFramesThroughAResize) {
  ASSERT_NO_FATAL_FAILURE(make_target(VK_SAMPLE_COUNT_4_BIT));
  EXPECT_EQ(target_->extent().width, 640u);
  EXPECT_EQ(target_->extent().height, 360u);
  EXPECT_TRUE(target_->color_format() == VK_FORMAT_B8G8R8A8_SRGB ||
              target_->color_format() == VK_FORMAT_R8G8B8A8_SRGB);
  EXPECT_EQ(target_->present_mode(), VK_PRESENT_MODE_FIFO_KHR);
  std::printf("samples %d, %u swap-chain images\n", static_cast<int>(target_->samples()),
              target_->swapchain_image_count());

  constexpr int kFrames = 120;
  constexpr int kResizeAt = 50;
  constexpr int kBeforeResize = 30;
  std::optional<CapturedFrame> before;
  for (int frame = 0; frame < kFrames; ++frame) {
    if (frame == kResizeAt) {
      EXPECT_EQ(target_->recreate_count(), 0u);
      window_->set_size(800, 450);
    }
    const bool capture = frame == kBeforeResize || frame == kFrames - 1;
    ASSERT_NO_FATAL_FAILURE(render(frame, capture));
    if (frame == kBeforeResize) {
      auto captured = target_->take_capture();
      ASSERT_TRUE(captured) << captured.error().message;
      before = std::move(*captured);
    }
  }
  auto after = target_->take_capture();
  ASSERT_TRUE(after) << after.error().message;

  // The resize reached the swap chain: recreated, new size.
  EXPECT_GE(target_->recreate_count(), 1u);
  EXPECT_EQ(target_->extent().width, 800u);
  EXPECT_EQ(target_->extent().height, 450u);

  ASSERT_TRUE(before.has_value());
  expect_frame(*before, {640, 360}, animated_clear(kBeforeResize));
  expect_frame(*after, {800, 450}, animated_clear(kFrames - 1));
  keep_artifact(*before, "window_640x360.png");
  keep_artifact(*after, "window_800x450.png");
  if (target_->samples() != VK_SAMPLE_COUNT_1_BIT) {
    // Edge pixels partly covered by the triangle are averaged by the resolve.
    const std::size_t blended = blended_pixels(*after, srgb_of(animated_clear(kFrames - 1)));
    EXPECT_GT(blended, 100u);
    EXPECT_LT(blended, std::size_t{800} * 450 / 20);
  }
  EXPECT_FALSE(target_->take_capture()) << "a capture is taken once";
}

// Without MSAA every pixel is the clear or the triangle colour; with it the test above sees
// blends, so it measures the resolve and not the rasteriser.
TEST_F(WindowTargetTest, SingleSampleHasNoBlendedEdges) {
  ASSERT_NO_FATAL_FAILURE(make_target(VK_SAMPLE_COUNT_1_BIT));
  EXPECT_EQ(target_->samples(), VK_SAMPLE_COUNT_1_BIT);
  constexpr int kFrames = 6;
  for (int frame = 0; frame < kFrames; ++frame) {
    ASSERT_NO_FATAL_FAILURE(render(frame, frame == kFrames - 1));
  }
  auto captured = target_->take_capture();
  ASSERT_TRUE(captured) << captured.error().message;
  expect_frame(*captured, {640, 360}, animated_clear(kFrames - 1));
  EXPECT_EQ(blended_pixels(*captured, srgb_of(animated_clear(kFrames - 1))), 0u);
  keep_artifact(*captured, "window_640x360_1x.png");
}

// Dynamic resolution: the main pass at half the size per axis, stretched over the whole image —
// the same picture (the clear colour in the corners, the triangle in the middle) with the
// triangle's edges softened by the linear filter; scale 1 gives the sharp frame back. The
// validation layer, with its synchronization checks, stays silent (TearDown).
TEST_F(WindowTargetTest, AScaledMainPassIsStretchedOverTheWholeImage) {
  ASSERT_NO_FATAL_FAILURE(make_target(VK_SAMPLE_COUNT_1_BIT));
  target_->set_render_scale(0.5f);
  if (target_->render_scale() == 1.0f) GTEST_SKIP() << "this surface cannot be blitted to";
  EXPECT_EQ(target_->render_extent().width, 320u);
  EXPECT_EQ(target_->render_extent().height, 180u);
  EXPECT_EQ(target_->extent().width, 640u) << "the window's size is unchanged";
  constexpr int kFrames = 6;
  for (int frame = 0; frame < kFrames; ++frame) {
    ASSERT_NO_FATAL_FAILURE(render(frame, frame == kFrames - 1));
  }
  auto scaled = target_->take_capture();
  ASSERT_TRUE(scaled) << scaled.error().message;
  expect_frame(*scaled, {640, 360}, animated_clear(kFrames - 1));
  EXPECT_GT(blended_pixels(*scaled, srgb_of(animated_clear(kFrames - 1))), 100u)
      << "stretched edges are filtered";
  keep_artifact(*scaled, "window_640x360_scaled_half.png");

  target_->set_render_scale(1.0f);
  for (int frame = 0; frame < 3; ++frame) ASSERT_NO_FATAL_FAILURE(render(frame, frame == 2));
  auto full = target_->take_capture();
  ASSERT_TRUE(full) << full.error().message;
  EXPECT_EQ(blended_pixels(*full, srgb_of(animated_clear(2))), 0u);
  target_->set_render_scale(0.1f);
  EXPECT_EQ(target_->render_scale(), 0.25f) << "clamped";
}

// With MSAA the samples are resolved into the scaled image, which is then stretched.
TEST_F(WindowTargetTest, AScaledMsaaPassIsResolvedThenStretched) {
  ASSERT_NO_FATAL_FAILURE(make_target(VK_SAMPLE_COUNT_4_BIT));
  target_->set_render_scale(0.75f);
  if (target_->render_scale() == 1.0f) GTEST_SKIP() << "this surface cannot be blitted to";
  EXPECT_EQ(target_->render_extent().width, 480u);
  EXPECT_EQ(target_->render_extent().height, 270u);
  constexpr int kFrames = 4;
  for (int frame = 0; frame < kFrames; ++frame) {
    ASSERT_NO_FATAL_FAILURE(render(frame, frame == kFrames - 1));
  }
  auto captured = target_->take_capture();
  ASSERT_TRUE(captured) << captured.error().message;
  expect_frame(*captured, {640, 360}, animated_clear(kFrames - 1));
}

#ifdef TUTTI_TEST_X11_PIXELS
// What was presented reaches the X server: the window shows the clear colour in a corner and
// the triangle in the middle. Presentation may be asynchronous (Mesa's FIFO queue thread), so
// the same frame is presented repeatedly until it shows, for at most ~2 s.
TEST_F(WindowTargetTest, PresentedFramesReachTheXServer) {
  ASSERT_NO_FATAL_FAILURE(make_target(VK_SAMPLE_COUNT_4_BIT));
  const ClearColor clear{0.0f, 0.5f, 0.0f, 1.0f};
  const Rgb want_clear = srgb_of(clear);
  const Rgb want_triangle = srgb(kTriangle[0], kTriangle[1], kTriangle[2]);
  const auto matches = [](std::optional<test::ScreenPixel> got, Rgb want) {
    return got && std::abs(got->r - want.r) <= 2 && std::abs(got->g - want.g) <= 2 &&
           std::abs(got->b - want.b) <= 2;
  };
  std::optional<test::ScreenPixel> corner, centre;
  for (int frame = 0; frame < 200; ++frame) {
    window_->poll_events();
    auto recording = target_->begin_frame();
    ASSERT_TRUE(recording) << recording.error().message;
    target_->begin_main_pass(clear);
    pipeline_->draw(recording->commands, *mesh_, glm::mat4(1.0f));
    ASSERT_TRUE(target_->end_frame());
    corner = test::read_window_pixel(window_->handle(), 3, 3);
    centre = test::read_window_pixel(window_->handle(), 320, 180);
    if (frame >= 3 && matches(corner, want_clear) && matches(centre, want_triangle)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(corner && centre) << "XGetImage failed";
  EXPECT_TRUE(matches(corner, want_clear))
      << "corner on screen " << corner->r << " " << corner->g << " " << corner->b << ", expected "
      << want_clear.r << " " << want_clear.g << " " << want_clear.b;
  EXPECT_TRUE(matches(centre, want_triangle))
      << "centre on screen " << centre->r << " " << centre->g << " " << centre->b << ", expected "
      << want_triangle.r << " " << want_triangle.g << " " << want_triangle.b;
}
#endif

TEST_F(WindowTargetTest, FrameWithoutMainPassIsClearedAndPresented) {
  ASSERT_NO_FATAL_FAILURE(make_target(VK_SAMPLE_COUNT_4_BIT));
  target_->capture_next_frame();
  auto recording = target_->begin_frame();
  ASSERT_TRUE(recording) << recording.error().message;
  EXPECT_FALSE(target_->begin_frame()) << "a frame is already being recorded";
  auto id = target_->end_frame();
  ASSERT_TRUE(id) << id.error().message;
  EXPECT_FALSE(target_->end_frame()) << "no frame is being recorded";
  auto captured = target_->take_capture();
  ASSERT_TRUE(captured) << captured.error().message;
  EXPECT_TRUE(pixel_near(captured->rgba, captured->width, 320, 180, {0, 0, 0}))
      << pixel_string(captured->rgba, captured->width, 320, 180);
}

TEST_F(WindowTargetTest, ClampsSampleCountsAndRejectsOthers) {
  auto eight = WindowTarget::create(*context_, *window_, {.samples = VK_SAMPLE_COUNT_8_BIT});
  ASSERT_TRUE(eight) << eight.error().message;
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(context_->physical_device(), &properties);
  const VkSampleCountFlags supported = properties.limits.framebufferColorSampleCounts &
                                       properties.limits.framebufferDepthSampleCounts;
  const VkSampleCountFlagBits chosen = (*eight)->samples();
  EXPECT_LE(chosen, VK_SAMPLE_COUNT_8_BIT);
  EXPECT_NE(supported & chosen, 0u);
  for (VkSampleCountFlagBits higher :
       {VK_SAMPLE_COUNT_8_BIT, VK_SAMPLE_COUNT_4_BIT, VK_SAMPLE_COUNT_2_BIT}) {
    if (higher > chosen && (supported & higher) != 0) ADD_FAILURE() << higher << " was possible";
  }
  eight->reset();  // one surface per window at a time

  auto three =
      WindowTarget::create(*context_, *window_, {.samples = static_cast<VkSampleCountFlagBits>(3)});
  ASSERT_FALSE(three);
  EXPECT_NE(three.error().message.find("1, 2, 4 or 8"), std::string::npos) << three.error().message;
}

TEST(WindowTargetWithoutPresentation, ContextWithoutSwapchainIsAnError) {
  if (!have_display()) {
    std::printf("SKIPPED: no display\n");
    GTEST_SKIP() << "DISPLAY is not set";
  }
  auto window = Window::create({.width = 64, .height = 64});
  ASSERT_TRUE(window) << window.error().message;
  auto context = VulkanContext::create({});
  if (!context && test::is_no_device_error(context.error())) GTEST_SKIP();
  ASSERT_TRUE(context) << context.error().message;
  auto target = WindowTarget::create(**context, **window);
  ASSERT_FALSE(target);
  EXPECT_NE(target.error().message.find("require_presentation"), std::string::npos)
      << target.error().message;
}

// Runs with or without a display: DISPLAY is taken away for the duration.
TEST(Window, NoDisplayIsAnErrorValue) {
  const char* display = std::getenv("DISPLAY");
  const std::optional<std::string> saved =
      display != nullptr ? std::optional<std::string>(display) : std::nullopt;
  unsetenv("DISPLAY");
  auto window = Window::create({.width = 64, .height = 64});
  if (saved) setenv("DISPLAY", saved->c_str(), 1);
  ASSERT_FALSE(window);
  EXPECT_TRUE(is_no_display_error(window.error())) << window.error().message;
  EXPECT_NE(window.error().message.find("tutti render"), std::string::npos);
}

TEST(Window, ZeroSizeIsAnError) {
  auto window = Window::create({.width = 0, .height = 10});
  ASSERT_FALSE(window);
  EXPECT_NE(window.error().message.find("0x10"), std::string::npos) << window.error().message;
}

}  // namespace
}  // namespace tutti::render
