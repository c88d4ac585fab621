// SPDX-License-Identifier: MIT
#include <tutti/render/offscreen_target.hpp>

#include <cstring>
#include <string>

#include <tutti/render/image_barrier.hpp>
#include <tutti/render/vk_result.hpp>

namespace tutti::render {
namespace {

// Readback rows start on this boundary; a typical optimal copy pitch on GPUs.
constexpr std::uint32_t kRowAlignmentBytes = 256;

}  // namespace

Result<std::unique_ptr<OffscreenTarget>> OffscreenTarget::create(VulkanContext& context,
                                                                 std::uint32_t width,
                                                                 std::uint32_t height,
                                                                 std::uint32_t ring_size,
                                                                 VkSampleCountFlagBits samples) {
  if (width == 0 || height == 0 || ring_size == 0) {
    return Error{"offscreen target: size " + std::to_string(width) + "x" + std::to_string(height) +
                 " and ring size " + std::to_string(ring_size) + " must be at least 1"};
  }
  if (samples != VK_SAMPLE_COUNT_1_BIT && samples != VK_SAMPLE_COUNT_2_BIT &&
      samples != VK_SAMPLE_COUNT_4_BIT && samples != VK_SAMPLE_COUNT_8_BIT) {
    return Error{"offscreen target: " + std::to_string(samples) +
                 " samples per pixel: must be 1, 2, 4 or 8"};
  }
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(context.physical_device(), &properties);
  const VkSampleCountFlags supported = properties.limits.framebufferColorSampleCounts &
                                       properties.limits.framebufferDepthSampleCounts;
  if ((supported & samples) == 0) {
    return Error{"offscreen target: the device " + context.device_info().name + " cannot render " +
                 std::to_string(samples) + " samples per pixel"};
  }
  std::unique_ptr<OffscreenTarget> target(new OffscreenTarget(context));
  target->samples_ = samples;
  target->extent_ = {width, height};
  target->depth_format_ = choose_depth_format(context.physical_device());
  const std::uint32_t tight_row = width * 4;
  target->row_pitch_bytes_ =
      (tight_row + kRowAlignmentBytes - 1) / kRowAlignmentBytes * kRowAlignmentBytes;

  const VkPhysicalDevice physical = context.physical_device();
  const VkDevice device = context.device();
  target->slots_.resize(ring_size);
  for (Slot& slot : target->slots_) {
    Result<DeviceImage> color =
        create_image(physical, device, kColorFormat, target->extent_,
                     VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                     VK_IMAGE_ASPECT_COLOR_BIT);
    if (!color) return color.error();
    slot.color = std::move(*color);
    Result<DeviceImage> depth = create_image(
        physical, device, target->depth_format_, target->extent_,
        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
        VK_IMAGE_ASPECT_DEPTH_BIT, samples);
    if (!depth) return depth.error();
    slot.depth = std::move(*depth);
    if (samples != VK_SAMPLE_COUNT_1_BIT) {
      Result<DeviceImage> msaa = create_image(
          physical, device, kColorFormat, target->extent_,
          VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
          VK_IMAGE_ASPECT_COLOR_BIT, samples);
      if (!msaa) return msaa.error();
      slot.msaa_color = std::move(*msaa);
    }
    Result<DeviceBuffer> readback =
        create_host_buffer(physical, device, VkDeviceSize{target->row_pitch_bytes_} * height,
                           VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    if (!readback) return readback.error();
    slot.readback = std::move(*readback);

    Result<VkCommandBuffer> commands = context.allocate_command_buffer();
    if (!commands) return commands.error();
    slot.commands = *commands;
    Result<DeviceHandle<VkFence>> fence = context.create_fence(false);
    if (!fence) return fence.error();
    slot.done = std::move(*fence);
  }
  return target;
}

OffscreenTarget::~OffscreenTarget() {
  for (Slot& slot : slots_) {
    if (slot.submitted) {
      VkFence fence = slot.done.get();
      vkWaitForFences(context_.device(), 1, &fence, VK_TRUE, UINT64_MAX);
    }
    if (slot.commands != VK_NULL_HANDLE) {
      vkFreeCommandBuffers(context_.device(), context_.command_pool(), 1, &slot.commands);
    }
  }
}

Status OffscreenTarget::wait(Slot& slot) {
  if (!slot.submitted) return Status::success();
  VkFence fence = slot.done.get();
  if (VkResult r = vkWaitForFences(context_.device(), 1, &fence, VK_TRUE, UINT64_MAX);
      r != VK_SUCCESS) {
    return vk_error("vkWaitForFences", r);
  }
  slot.submitted = false;
  return vk_check("vkResetFences", vkResetFences(context_.device(), 1, &fence));
}

Result<RecordingFrame> OffscreenTarget::begin_frame() {
  if (recording_ != nullptr) {
    return Error{"offscreen target: begin_frame while frame " +
                 std::to_string(recording_->frame_id) + " is still being recorded"};
  }
  Slot& slot = slots_[(next_id_ - 1) % slots_.size()];
  if (Status s = wait(slot); !s) return s.error();
  slot.frame_id = 0;  // its old pixels are gone from here on

  if (VkResult r = vkResetCommandBuffer(slot.commands, 0); r != VK_SUCCESS) {
    return vk_error("vkResetCommandBuffer", r);
  }
  VkCommandBufferBeginInfo begin =
      vk_struct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  if (VkResult r = vkBeginCommandBuffer(slot.commands, &begin); r != VK_SUCCESS) {
    return vk_error("vkBeginCommandBuffer", r);
  }
  slot.frame_id = next_id_++;
  recording_ = &slot;
  return RecordingFrame{slot.commands, slot.frame_id};
}

void OffscreenTarget::begin_main_pass(const ClearColor& clear) {
  if (recording_ == nullptr || main_pass_open_) return;  // precondition broken: record nothing
  Slot& slot = *recording_;
  main_pass_open_ = true;
  main_pass_recorded_ = true;
  const bool msaa = samples_ != VK_SAMPLE_COUNT_1_BIT;

  // The previous frame in this slot last read colour in a copy and wrote depth in the
  // fragment tests; every attachment is cleared, so their contents need not survive.
  const VkImageMemoryBarrier2 to_color =
      image_barrier(slot.color.image.get(), VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                    VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  const VkImageMemoryBarrier2 to_depth = image_barrier(
      slot.depth.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT,
      VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
      VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
          VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
  if (msaa) {
    const VkImageMemoryBarrier2 to_msaa = image_barrier(
        slot.msaa_color.image.get(), VK_IMAGE_ASPECT_COLOR_BIT,
        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
        VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    record_image_barriers(slot.commands, {to_color, to_depth, to_msaa});
  } else {
    record_image_barriers(slot.commands, {to_color, to_depth});
  }

  VkRenderingAttachmentInfo color =
      vk_struct<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
  color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  color.clearValue.color = {{clear.r, clear.g, clear.b, clear.a}};
  if (msaa) {
    color.imageView = slot.msaa_color.view.get();
    color.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
    color.resolveImageView = slot.color.view.get();
    color.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  } else {
    color.imageView = slot.color.view.get();
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  }
  VkRenderingAttachmentInfo depth =
      vk_struct<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
  depth.imageView = slot.depth.view.get();
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo rendering = vk_struct<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
  rendering.renderArea = {{0, 0}, extent_};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &color;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(slot.commands, &rendering);

  const VkViewport viewport{
      0.0f, 0.0f, static_cast<float>(extent_.width), static_cast<float>(extent_.height),
      0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent_};
  vkCmdSetViewport(slot.commands, 0, 1, &viewport);
  vkCmdSetScissor(slot.commands, 0, 1, &scissor);
}

void OffscreenTarget::end_main_pass() {
  if (recording_ == nullptr || !main_pass_open_) return;
  vkCmdEndRendering(recording_->commands);
  main_pass_open_ = false;
}

Result<RecordingFrame> OffscreenTarget::begin_frame(const ClearColor& clear) {
  Result<RecordingFrame> frame = begin_frame();
  if (frame) begin_main_pass(clear);
  return frame;
}

Result<std::uint64_t> OffscreenTarget::end_frame() {
  if (recording_ == nullptr) return Error{"offscreen target: end_frame without begin_frame"};
  Slot& slot = *recording_;
  // A frame without a main pass still has defined pixels: the colour image is cleared to black.
  if (!main_pass_recorded_) begin_main_pass(ClearColor{});
  end_main_pass();
  main_pass_recorded_ = false;
  recording_ = nullptr;

  const VkImageMemoryBarrier2 to_copy = image_barrier(
      slot.color.image.get(), VK_IMAGE_ASPECT_COLOR_BIT,
      VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
      VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  record_image_barriers(slot.commands, {to_copy});

  VkBufferImageCopy region{};
  region.bufferOffset = 0;
  region.bufferRowLength = row_pitch_bytes_ / 4;  // in texels; rows are padded
  region.bufferImageHeight = 0;
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {extent_.width, extent_.height, 1};
  vkCmdCopyImageToBuffer(slot.commands, slot.color.image.get(),
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, slot.readback.buffer.get(), 1,
                         &region);

  VkBufferMemoryBarrier2 to_host =
      vk_struct<VkBufferMemoryBarrier2>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2);
  to_host.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
  to_host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  to_host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
  to_host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
  to_host.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  to_host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  to_host.buffer = slot.readback.buffer.get();
  to_host.offset = 0;
  to_host.size = VK_WHOLE_SIZE;
  VkDependencyInfo after_copy = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
  after_copy.bufferMemoryBarrierCount = 1;
  after_copy.pBufferMemoryBarriers = &to_host;
  vkCmdPipelineBarrier2(slot.commands, &after_copy);

  if (VkResult r = vkEndCommandBuffer(slot.commands); r != VK_SUCCESS) {
    slot.frame_id = 0;
    return vk_error("vkEndCommandBuffer", r);
  }
  VkCommandBufferSubmitInfo command_info =
      vk_struct<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
  command_info.commandBuffer = slot.commands;
  VkSubmitInfo2 submit = vk_struct<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &command_info;
  if (VkResult r = vkQueueSubmit2(context_.graphics_queue(), 1, &submit, slot.done.get());
      r != VK_SUCCESS) {
    slot.frame_id = 0;
    return vk_error("vkQueueSubmit2", r);
  }
  slot.submitted = true;
  return slot.frame_id;
}

Status OffscreenTarget::read_pixels(std::uint64_t id, std::vector<std::uint8_t>& rgba) {
  Slot* slot = nullptr;
  for (Slot& candidate : slots_) {
    if (id != 0 && candidate.frame_id == id) slot = &candidate;
  }
  if (slot == nullptr) {
    return Error{"offscreen target: frame " + std::to_string(id) +
                 " is not in the ring (never rendered, or overwritten by a later frame)"};
  }
  if (slot == recording_) {
    return Error{"offscreen target: frame " + std::to_string(id) + " has not been ended"};
  }
  if (Status s = wait(*slot); !s) return s;
  if (Status s = invalidate_for_host_read(context_.device(), slot->readback); !s) return s;

  const std::size_t tight_row = std::size_t{extent_.width} * 4;
  rgba.resize(tight_row * extent_.height);
  const auto* source = static_cast<const std::uint8_t*>(slot->readback.mapped);
  for (std::uint32_t y = 0; y < extent_.height; ++y) {
    std::memcpy(rgba.data() + y * tight_row, source + std::size_t{y} * row_pitch_bytes_, tight_row);
  }
  return Status::success();
}

}  // namespace tutti::render
