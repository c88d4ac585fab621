// SPDX-License-Identifier: MIT
// ImGuiLayer under a real window (ctest runs this program under `xvfb-run`): an ImGui window
// drawn in WindowTarget's overlay pass over a cleared, multisampled 3D pass, captured. Validation
// with synchronization validation is on; any message fails. Without a display or a Vulkan
// device: "[  SKIPPED ]".
#include <tutti/runtime/imgui_layer.hpp>

#include <gtest/gtest.h>
#include <imgui.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <tutti/image/png.hpp>
#include "render/render_test_support.hpp"
#include <tutti/render/vulkan_context.hpp>
#include <tutti/render/window.hpp>
#include <tutti/render/window_target.hpp>

namespace tutti::runtime {
namespace {

using render::test::pixel_near;
using render::test::srgb;

constexpr render::ClearColor kClear{0.05f, 0.1f, 0.3f, 1.0f};

bool have_display() {
  const char* display = std::getenv("DISPLAY");
  return display != nullptr && display[0] != '\0';
}

class ImGuiLayerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!have_display()) {
      std::printf("SKIPPED: no display\n");
      GTEST_SKIP() << "DISPLAY is not set";
    }
    auto window = render::Window::create(
        {.width = 480, .height = 320, .title = "imgui test", .resizable = false});
    ASSERT_TRUE(window) << window.error().message;
    window_ = std::move(*window);
    render::VulkanContextOptions options;
    options.validation = true;
    options.synchronization_validation = true;
    render::require_presentation(*window_, options);
    auto context = render::VulkanContext::create(options);
    if (!context && render::test::is_no_device_error(context.error())) {
      std::printf("SKIPPED: no Vulkan device\n");
      GTEST_SKIP() << context.error().message;
    }
    ASSERT_TRUE(context) << context.error().message;
    context_ = std::move(*context);
    log_ = context_->validation_log();
  }

  void TearDown() override {
    layer_.reset();
    target_.reset();
    context_.reset();
    window_.reset();
    if (log_ == nullptr) return;
    const std::vector<std::string> messages = log_->messages();
    for (const std::string& message : messages) std::printf("%s\n", message.c_str());
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s), printed above";
  }

  std::unique_ptr<render::Window> window_;
  std::unique_ptr<render::VulkanContext> context_;
  std::shared_ptr<const render::ValidationLog> log_;
  std::unique_ptr<render::WindowTarget> target_;
  std::unique_ptr<ImGuiLayer> layer_;
};

TEST_F(ImGuiLayerTest, DrawsAWindowOverTheMainPass) {
  auto target = render::WindowTarget::create(*context_, *window_,
                                             {.samples = VK_SAMPLE_COUNT_4_BIT,
                                              .present_mode = VK_PRESENT_MODE_FIFO_KHR,
                                              .frames_in_flight = 2});
  ASSERT_TRUE(target) << target.error().message;
  target_ = std::move(*target);
  ASSERT_NE(target_->overlay_render_pass(), VK_NULL_HANDLE);
  auto layer = ImGuiLayer::create(*context_, *window_, *target_);
  ASSERT_TRUE(layer) << layer.error().message;
  layer_ = std::move(*layer);
  EXPECT_FALSE(ImGuiLayer::create(*context_, *window_, *target_));  // one at a time

  constexpr int kFrames = 6;
  for (int frame = 0; frame < kFrames; ++frame) {
    window_->poll_events();
    layer_->new_frame();
    ImGui::SetNextWindowPos(ImVec2(40, 40), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(200, 120), ImGuiCond_Always);
    ImGui::Begin("Transport");
    ImGui::Text("frame %d", frame);
    ImGui::Button("Play");
    ImGui::End();
    if (frame + 1 == kFrames) target_->capture_next_frame();
    auto recording = target_->begin_frame();
    ASSERT_TRUE(recording) << recording.error().message;
    target_->begin_main_pass(kClear);
    target_->end_main_pass();
    layer_->record_overlay(*recording, *target_);
    auto id = target_->end_frame();
    ASSERT_TRUE(id) << id.error().message;
  }
  auto captured = target_->take_capture();
  ASSERT_TRUE(captured) << captured.error().message;
  const std::filesystem::path dir = TUTTI_RUNTIME_ARTIFACT_DIR;
  std::error_code ignored;
  std::filesystem::create_directories(dir, ignored);
  EXPECT_TRUE(image::write_png(dir / "imgui_overlay.png", captured->rgba, captured->width,
                               captured->height));
  const render::test::Rgb clear = srgb(kClear.r, kClear.g, kClear.b);
  // Outside the ImGui window: the main pass's clear colour.
  EXPECT_TRUE(pixel_near(captured->rgba, captured->width, 10, 10, clear));
  EXPECT_TRUE(pixel_near(captured->rgba, captured->width, 400, 250, clear));
  // Inside it (the title bar and the body): ImGui's colours, not the clear colour.
  EXPECT_FALSE(pixel_near(captured->rgba, captured->width, 140, 48, clear));
  EXPECT_FALSE(pixel_near(captured->rgba, captured->width, 200, 140, clear));
}

TEST_F(ImGuiLayerTest, OverlayWithoutAMainPassStillPresents) {
  auto target = render::WindowTarget::create(*context_, *window_);
  ASSERT_TRUE(target) << target.error().message;
  target_ = std::move(*target);
  auto layer = ImGuiLayer::create(*context_, *window_, *target_);
  ASSERT_TRUE(layer) << layer.error().message;
  layer_ = std::move(*layer);
  for (int frame = 0; frame < 3; ++frame) {
    window_->poll_events();
    auto recording = target_->begin_frame();
    ASSERT_TRUE(recording) << recording.error().message;
    layer_->new_frame();
    ImGui::ShowDemoWindow();
    layer_->record_overlay(*recording, *target_);  // the main pass is begun (black) for it
    ASSERT_TRUE(target_->end_frame());
  }
}

TEST_F(ImGuiLayerTest, OverlayFollowsAResize) {
  auto target = render::WindowTarget::create(*context_, *window_,
                                             {.samples = VK_SAMPLE_COUNT_4_BIT,
                                              .present_mode = VK_PRESENT_MODE_FIFO_KHR,
                                              .frames_in_flight = 2});
  ASSERT_TRUE(target) << target.error().message;
  target_ = std::move(*target);
  auto layer = ImGuiLayer::create(*context_, *window_, *target_);
  ASSERT_TRUE(layer) << layer.error().message;
  layer_ = std::move(*layer);
  constexpr int kFrames = 40;
  for (int frame = 0; frame < kFrames; ++frame) {
    if (frame == 5) window_->set_size(400, 300);
    window_->poll_events();
    layer_->new_frame();
    ImGui::SetNextWindowPos(ImVec2(20, 20), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(160, 100), ImGuiCond_Always);
    ImGui::Begin("Resized");
    ImGui::Text("frame %d", frame);
    ImGui::End();
    if (frame + 1 == kFrames) target_->capture_next_frame();
    auto recording = target_->begin_frame();
    ASSERT_TRUE(recording) << recording.error().message;
    target_->begin_main_pass(kClear);
    layer_->record_overlay(*recording, *target_);  // ends the main pass itself
    ASSERT_TRUE(target_->end_frame());
  }
  EXPECT_GE(target_->recreate_count(), 1u);
  auto captured = target_->take_capture();
  ASSERT_TRUE(captured) << captured.error().message;
  EXPECT_EQ(captured->width, 400u);
  EXPECT_EQ(captured->height, 300u);
  const render::test::Rgb clear = srgb(kClear.r, kClear.g, kClear.b);
  EXPECT_TRUE(pixel_near(captured->rgba, captured->width, 390, 290, clear));
  EXPECT_FALSE(pixel_near(captured->rgba, captured->width, 100, 70, clear));
}

}  // namespace
}  // namespace tutti::runtime
