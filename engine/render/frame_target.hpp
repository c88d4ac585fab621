// SPDX-License-Identifier: MIT
#pragma once
// FrameTarget: where a frame is rendered — an offscreen image ring with readback
// (OffscreenTarget) or a window's swap chain (WindowTarget). One interface, so the renderer never
// asks "headless?" (Filament's headless swap chain behind the same SwapChain interface).
//
// A frame is recorded in four steps:
//
//   auto frame = target.begin_frame();     // command buffer begun, outside any rendering:
//   shadows.record(frame->commands, ...);  //   record depth-only passes here
//   target.begin_main_pass(clear);         // colour + depth cleared, viewport/scissor = extent
//   pipeline.draw(frame->commands, ...);   // draw into samples()-sample attachments
//   target.end_main_pass();                // MSAA colour resolved into the final image
//   auto id = target.end_frame();          // submitted (offscreen: copied for readback;
//                                          //   window: presented)
//
// Pipelines must be built for color_format(), depth_format() and samples(). Colour attachments
// are sRGB: shaders write linear light. One thread at a time; the VulkanContext outlives it.

#include <vulkan/vulkan.h>

#include <cstdint>

#include <tutti/core/result.hpp>

namespace tutti::render {

// A sample count (1, 2, 4 or 8, as scene files and --msaa give it) as Vulkan's flag; anything
// else is 1 sample.
inline VkSampleCountFlagBits sample_count_flag(int samples) {
  switch (samples) {
    case 2:
      return VK_SAMPLE_COUNT_2_BIT;
    case 4:
      return VK_SAMPLE_COUNT_4_BIT;
    case 8:
      return VK_SAMPLE_COUNT_8_BIT;
    default:
      return VK_SAMPLE_COUNT_1_BIT;
  }
}

// Linear-light RGBA in [0, 1]; the sRGB attachment encodes it on store.
struct ClearColor {
  float r = 0.0f, g = 0.0f, b = 0.0f, a = 1.0f;
};

// A frame being recorded.
struct RecordingFrame {
  VkCommandBuffer commands = VK_NULL_HANDLE;
  std::uint64_t id = 0;  // OffscreenTarget: pass to read_pixels() after end_frame()
};

class FrameTarget {
 public:
  virtual ~FrameTarget() = default;

  virtual VkExtent2D extent() const = 0;
  virtual VkFormat color_format() const = 0;
  virtual VkFormat depth_format() const = 0;
  virtual VkSampleCountFlagBits samples() const = 0;
  // Frames that may be in flight at once. Frame ids count up by one from 1, and when
  // begin_frame() returns frame id, frame id - frames_in_flight() has finished on the device, so
  // per-frame data indexed by (id - 1) % frames_in_flight() is free to rewrite.
  virtual std::uint32_t frames_in_flight() const = 0;

  // An error if a frame is already being recorded.
  virtual Result<RecordingFrame> begin_frame() = 0;
  // Precondition: inside begin_frame/end_frame and no main pass open.
  virtual void begin_main_pass(const ClearColor& clear) = 0;
  virtual void end_main_pass() = 0;
  // Ends the main pass if it is still open, then submits. Returns the frame's id.
  virtual Result<std::uint64_t> end_frame() = 0;
};

}  // namespace tutti::render
