// SPDX-License-Identifier: MIT
#pragma once
// WindowTarget: a FrameTarget that presents to a Window through a Vulkan swap chain (Filament's
// VulkanSwapChain; vkguide's frame loop). Owns the surface, the swap chain and its image views,
// one depth attachment and, with MSAA, one multisampled colour attachment resolved into the
// swap-chain image at end_main_pass().
//
//   auto target = WindowTarget::create(context, window, {.samples = VK_SAMPLE_COUNT_4_BIT});
//   while (!window.should_close()) {
//     window.poll_events();
//     auto frame = target->begin_frame();       // waits for a frame slot, acquires an image
//     target->begin_main_pass(clear);
//     pipeline->draw(frame->commands, ...);     // pipeline built for samples()
//     target->end_frame();                      // resolve, present
//   }
//
// Overlay pass (for Dear ImGui, whose Vulkan backend needs a classic VkRenderPass): after the
// main pass, begin_overlay_pass() .. end_overlay_pass() draws over the resolved swap-chain image
// (one sample, loadOp LOAD) through overlay_render_pass() and a framebuffer per swap-chain image.
// The image stays in COLOR_ATTACHMENT_OPTIMAL between the passes; end_frame() moves it on to
// PRESENT_SRC (or TRANSFER_SRC for a capture, which therefore includes the overlay).
//
// Frames in flight: each slot has a command buffer, a fence and an image-available semaphore;
// each swap-chain image has its own render-finished semaphore (a present may still be waiting on
// it when the slot comes round again). The depth and MSAA attachments are shared by the slots and
// ordered by barriers.
//
// Resizing: when the window's framebuffer size differs from extent(), or acquire/present report
// VK_ERROR_OUT_OF_DATE_KHR or VK_SUBOPTIMAL_KHR, the next begin_frame() waits for the device to
// go idle and recreates the swap chain and the size-dependent attachments. While the window is
// minimised (0x0) begin_frame() blocks in Window::wait_events(); it returns an error if the
// window is asked to close meanwhile.
//
// Dynamic resolution: set_render_scale(s < 1) makes the main pass render s × extent() per axis
// into an image of its own (MSAA resolved there), which end_main_pass stretches over the
// swap-chain image with a linear filter before the overlay pass; extent() (and so the camera's
// aspect and the renderer's level-of-detail choice) stays the window's, so a change of scale
// never switches a mesh's detail level. Surfaces that cannot be blitted to keep scale 1.
//
// The context must be created with require_presentation(window, options) (window.hpp). The
// context and the window outlive the target. One thread (GLFW's main thread).

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/render/device_memory.hpp>
#include <tutti/render/frame_target.hpp>
#include <tutti/render/vulkan_context.hpp>
#include <tutti/render/window.hpp>

namespace tutti::render {

struct WindowTargetOptions {
  // 1, 2, 4 or 8; lowered to the largest count the device supports for both colour and depth
  // attachments (samples() reports what was chosen).
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  // Used when the surface supports it, else FIFO (always available; waits for vertical blank).
  VkPresentModeKHR present_mode = VK_PRESENT_MODE_FIFO_KHR;
  std::uint32_t frames_in_flight = 2;  // >= 1
};

// Pixels of one presented frame (capture_next_frame()).
struct CapturedFrame {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // tightly packed RGBA8, sRGB-encoded, top row first
};

class WindowTarget final : public FrameTarget {
 public:
  static Result<std::unique_ptr<WindowTarget>> create(VulkanContext& context, Window& window,
                                                      const WindowTargetOptions& options = {});
  ~WindowTarget() override;
  WindowTarget(const WindowTarget&) = delete;
  WindowTarget& operator=(const WindowTarget&) = delete;

  // The swap chain's current size in pixels; changes after a resize (at begin_frame()).
  VkExtent2D extent() const override { return extent_; }
  VkFormat color_format() const override { return color_format_; }  // B8G8R8A8_SRGB or R8...
  VkFormat depth_format() const override { return depth_format_; }
  VkSampleCountFlagBits samples() const override { return samples_; }
  std::uint32_t frames_in_flight() const override {
    return static_cast<std::uint32_t>(slots_.size());
  }
  VkPresentModeKHR present_mode() const { return present_mode_; }
  std::uint32_t swapchain_image_count() const { return static_cast<std::uint32_t>(images_.size()); }
  // How often the swap chain was recreated since create() (resize, out of date, suboptimal).
  std::uint32_t recreate_count() const { return recreate_count_; }

  // The main pass's share of extent() per axis, clamped to [0.25, 1]; takes effect at the next
  // begin_main_pass. render_scale() is what is used (1 when the surface cannot be blitted to).
  void set_render_scale(float scale);
  float render_scale() const { return can_blit_ ? render_scale_ : 1.0f; }
  // The main pass's size in pixels: extent() × render_scale(), at least 1 × 1.
  VkExtent2D render_extent() const;

  Result<RecordingFrame> begin_frame() override;
  void begin_main_pass(const ClearColor& clear) override;
  void end_main_pass() override;
  // Render pass for drawing over the finished image: one colour attachment of color_format(),
  // one sample, loaded and stored, COLOR_ATTACHMENT_OPTIMAL before and after. Fixed for the
  // target's life (the swap chain's format does not change when it is recreated).
  VkRenderPass overlay_render_pass() const { return overlay_pass_.get(); }
  // After the main pass (ended here if still open; begun with a black clear if never begun) and
  // before end_frame(). Viewport and scissor are set to extent(). One overlay pass per frame.
  void begin_overlay_pass();
  void end_overlay_pass();
  // One main pass per frame (a second begin_main_pass records nothing).
  // Submits and presents. A frame whose main pass was never begun is cleared to black.
  Result<std::uint64_t> end_frame() override;

  // The next frame that ends is also copied from its swap-chain image to host memory; call
  // before that frame's end_frame(). take_capture() then waits for it and returns the pixels.
  void capture_next_frame() { capture_requested_ = true; }
  // An error when no captured frame is pending.
  Result<CapturedFrame> take_capture();

 private:
  struct Slot {
    VkCommandBuffer commands = VK_NULL_HANDLE;
    DeviceHandle<VkFence> done;                 // signalled when its last submission finished
    DeviceHandle<VkSemaphore> image_available;  // signalled by vkAcquireNextImageKHR
  };

  WindowTarget(VulkanContext& context, Window& window) : context_(context), window_(window) {}
  Status create_swapchain();
  Status wait_while_minimised();
  void destroy_swapchain_images();
  Status create_overlay_render_pass();
  // The image's last writes before the present (or the capture's copy): its final barrier.
  void finish_image(bool capture);
  // Stretches scaled_color_'s render_extent() corner over the swap-chain image.
  void blit_scaled_image(VkCommandBuffer commands, VkExtent2D from);

  VulkanContext& context_;
  Window& window_;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkExtent2D extent_{};
  VkFormat color_format_ = VK_FORMAT_UNDEFINED;
  VkColorSpaceKHR color_space_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
  VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
  VkPresentModeKHR present_mode_ = VK_PRESENT_MODE_FIFO_KHR;
  bool can_copy_from_images_ = false;  // surface supports TRANSFER_SRC usage (capture)
  bool can_blit_ = false;              // TRANSFER_DST usage and linear blits of the format

  std::vector<VkImage> images_;  // owned by the swap chain
  std::vector<DeviceHandle<VkImageView>> image_views_;
  // Per swap-chain image index; grows, never shrinks, so a present still waiting on one keeps it.
  std::vector<DeviceHandle<VkSemaphore>> render_finished_;
  DeviceImage depth_;
  DeviceImage msaa_color_;    // only when samples_ > 1
  DeviceImage scaled_color_;  // the main pass's image when render_scale() < 1 (extent_-sized)
  float render_scale_ = 1.0f;
  bool scaled_pass_ = false;  // this frame's main pass renders into scaled_color_
  VkExtent2D scaled_area_{};  // this frame's main pass area
  DeviceHandle<VkRenderPass> overlay_pass_;
  std::vector<DeviceHandle<VkFramebuffer>> overlay_framebuffers_;  // per swap-chain image

  std::vector<Slot> slots_;
  std::uint32_t slot_index_ = 0;
  std::uint32_t image_index_ = 0;
  std::uint64_t next_id_ = 1;
  bool recording_ = false;
  bool main_pass_open_ = false;
  bool main_pass_done_ = false;
  bool overlay_open_ = false;
  bool overlay_done_ = false;
  bool needs_recreate_ = false;
  std::uint32_t recreate_count_ = 0;

  bool capture_requested_ = false;
  bool capture_pending_ = false;  // recorded into a submitted frame, not yet taken
  DeviceBuffer capture_buffer_;
  VkExtent2D capture_extent_{};
  VkFormat capture_format_ = VK_FORMAT_UNDEFINED;
};

}  // namespace tutti::render
