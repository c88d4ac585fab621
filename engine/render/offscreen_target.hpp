#pragma once
// OffscreenTarget: a ring of N frames, each a colour image (R8G8B8A8_SRGB), a depth image and a
// host-visible readback buffer, rendered with dynamic rendering (Sascha Willems'
// renderheadless; Filament's headless swap chain). The pixels of frame k can be read while frame
// k+1 renders: each ring slot has its own images, command buffer and fence.
//
//   auto frame = target.begin_frame(clear);       // waits only for this slot's previous frame
//   pipeline.draw(frame->commands, ...);          // record into the begun rendering
//   auto id = target.end_frame();                 // copy to the readback buffer, submit
//   target.read_pixels(*id, pixels);              // waits for that frame; tight RGBA8 rows
//
// The readback buffer's rows are padded to a 256-byte pitch (bufferRowLength), as a GPU's
// linear layout would be; read_pixels() honours it and returns tightly packed rows, top row
// first. One thread at a time; the context must outlive the target.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "core/result.hpp"
#include "render/device_memory.hpp"
#include "render/vulkan_context.hpp"

namespace tutti::render {

// Linear-light RGBA in [0, 1]; the sRGB attachment encodes it on store.
struct ClearColor {
  float r = 0.0f, g = 0.0f, b = 0.0f, a = 1.0f;
};

// A frame being recorded: the command buffer is inside vkCmdBeginRendering with viewport and
// scissor set to the whole target.
struct RecordingFrame {
  VkCommandBuffer commands = VK_NULL_HANDLE;
  std::uint64_t id = 0;  // pass to read_pixels() after end_frame()
};

class OffscreenTarget {
 public:
  static constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_SRGB;

  // width, height >= 1; ring_size >= 1 (2 lets readback overlap the next frame).
  static Result<std::unique_ptr<OffscreenTarget>> create(VulkanContext& context,
                                                         std::uint32_t width, std::uint32_t height,
                                                         std::uint32_t ring_size = 2);
  ~OffscreenTarget();
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;

  std::uint32_t width() const { return extent_.width; }
  std::uint32_t height() const { return extent_.height; }
  VkFormat color_format() const { return kColorFormat; }
  VkFormat depth_format() const { return depth_format_; }
  std::uint32_t ring_size() const { return static_cast<std::uint32_t>(slots_.size()); }
  // Bytes between rows in the readback buffer (>= width * 4).
  std::uint32_t readback_row_pitch_bytes() const { return row_pitch_bytes_; }

  // Starts the next frame: clears colour to `clear` and depth to 1.0. An error if a frame is
  // already being recorded.
  Result<RecordingFrame> begin_frame(const ClearColor& clear);
  // Ends rendering, records the copy into the readback buffer and submits. Returns the id.
  Result<std::uint64_t> end_frame();
  // Waits for frame `id` and writes width*height*4 bytes (RGBA8, sRGB-encoded, top row first)
  // into `rgba`. An error if the frame was never submitted or its slot has been reused since.
  Status read_pixels(std::uint64_t id, std::vector<std::uint8_t>& rgba);

 private:
  struct Slot {
    DeviceImage color;
    DeviceImage depth;
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
  std::uint32_t row_pitch_bytes_ = 0;
  std::vector<Slot> slots_;
  std::uint64_t next_id_ = 1;
  Slot* recording_ = nullptr;
};

}  // namespace tutti::render
