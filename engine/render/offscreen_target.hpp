// SPDX-License-Identifier: MIT
#pragma once
// OffscreenTarget: a ring of N frames, each a colour image (R8G8B8A8_SRGB), a depth image and a
// host-visible readback buffer, rendered with dynamic rendering (Sascha Willems'
// renderheadless; Filament's headless swap chain). The pixels of frame k can be read while frame
// k+1 renders: each ring slot has its own images, command buffer and fence. With samples > 1 the
// main pass draws into multisampled colour + depth attachments and resolves colour into the
// slot's image (MSAA).
//
//   auto frame = target.begin_frame();            // waits only for this slot's previous frame
//   ... record shadow passes ...
//   target.begin_main_pass(clear);
//   pipeline.draw(frame->commands, ...);          // record into the begun rendering
//   auto id = target.end_frame();                 // resolve, copy to the readback buffer, submit
//   target.read_pixels(*id, pixels);              // waits for that frame; tight RGBA8 rows
//
// begin_frame(clear) does the first and third step at once.
//
// The readback buffer's rows are padded to a 256-byte pitch (bufferRowLength), as a GPU's
// linear layout would be; read_pixels() honours it and returns tightly packed rows, top row
// first. One thread at a time; the context must outlive the target.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/render/device_memory.hpp>
#include <tutti/render/frame_target.hpp>
#include <tutti/render/vulkan_context.hpp>

namespace tutti::render {

class OffscreenTarget final : public FrameTarget {
 public:
  static constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_SRGB;

  // width, height >= 1; ring_size >= 1 (2 lets readback overlap the next frame); samples 1, 2,
  // 4 or 8 (an error if the device cannot multisample colour and depth that many times).
  static Result<std::unique_ptr<OffscreenTarget>> create(
      VulkanContext& context, std::uint32_t width, std::uint32_t height,
      std::uint32_t ring_size = 2, VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);
  ~OffscreenTarget() override;
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;

  std::uint32_t width() const { return extent_.width; }
  std::uint32_t height() const { return extent_.height; }
  VkExtent2D extent() const override { return extent_; }
  VkFormat color_format() const override { return kColorFormat; }
  VkFormat depth_format() const override { return depth_format_; }
  VkSampleCountFlagBits samples() const override { return samples_; }
  std::uint32_t frames_in_flight() const override { return ring_size(); }
  std::uint32_t ring_size() const { return static_cast<std::uint32_t>(slots_.size()); }
  // Bytes between rows in the readback buffer (>= width * 4).
  std::uint32_t readback_row_pitch_bytes() const { return row_pitch_bytes_; }

  // Starts the next frame (command buffer begun, no rendering yet). An error if a frame is
  // already being recorded.
  Result<RecordingFrame> begin_frame() override;
  // Clears colour to `clear` and depth to 1.0 and begins rendering with viewport and scissor set
  // to the whole target.
  void begin_main_pass(const ClearColor& clear) override;
  void end_main_pass() override;
  // begin_frame() + begin_main_pass(clear).
  Result<RecordingFrame> begin_frame(const ClearColor& clear);
  // Ends the main pass if open, records the copy into the readback buffer and submits. Returns
  // the id.
  Result<std::uint64_t> end_frame() override;
  // Waits for frame `id` and writes width*height*4 bytes (RGBA8, sRGB-encoded, top row first)
  // into `rgba`. An error if the frame was never submitted or its slot has been reused since.
  Status read_pixels(std::uint64_t id, std::vector<std::uint8_t>& rgba);

 private:
  struct Slot {
    DeviceImage color;
    DeviceImage depth;
    DeviceImage msaa_color;  // only when samples > 1; resolved into `color`
    DeviceBuffer readback;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    DeviceHandle<VkFence> done;  // signalled when the slot's last submission finished
    std::uint64_t frame_id = 0;  // 0: never used
    bool submitted = false;
  };

  explicit OffscreenTarget(VulkanContext& context) : context_(context) {}
  Status wait(Slot& slot);

  VulkanContext& context_;
  VkExtent2D extent_{};
  VkFormat depth_format_ = VK_FORMAT_UNDEFINED;
  VkSampleCountFlagBits samples_ = VK_SAMPLE_COUNT_1_BIT;
  std::uint32_t row_pitch_bytes_ = 0;
  std::vector<Slot> slots_;
  std::uint64_t next_id_ = 1;
  Slot* recording_ = nullptr;
  bool main_pass_open_ = false;
  bool main_pass_recorded_ = false;  // this frame has had its main pass
};

}  // namespace tutti::render
