// SPDX-License-Identifier: MIT
#include <tutti/render/buffer_upload.hpp>

#include <algorithm>
#include <cstring>

#include <tutti/render/vk_result.hpp>

namespace tutti::render {
namespace {

Result<DeviceBuffer> create_buffer(VulkanContext& context, VkDeviceSize size_bytes,
                                   VkBufferUsageFlags usage, VkMemoryPropertyFlags required,
                                   VkMemoryPropertyFlags preferred, bool map) {
  return render::create_buffer(context.physical_device(), context.device(), size_bytes, usage,
                               required, preferred, map);
}

}  // namespace

Result<DeviceBuffer> create_frame_buffer(VulkanContext& context, VkDeviceSize size_bytes,
                                         VkBufferUsageFlags usage) {
  return create_buffer(context, std::max<VkDeviceSize>(size_bytes, 16), usage,
                       VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT, VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                       true);
}

Status flush_for_device_read(VkDevice device, const DeviceBuffer& buffer) {
  if (buffer.coherent) return Status::success();
  VkMappedMemoryRange range = vk_struct<VkMappedMemoryRange>(VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE);
  range.memory = buffer.memory.get();
  range.size = VK_WHOLE_SIZE;
  return vk_check("vkFlushMappedMemoryRanges", vkFlushMappedMemoryRanges(device, 1, &range));
}

Result<DeviceBuffer> create_device_buffer_with_data(VulkanContext& context,
                                                    std::span<const std::byte> bytes,
                                                    VkBufferUsageFlags usage) {
  const VkDeviceSize size = std::max<VkDeviceSize>(bytes.size(), 16);
  Result<DeviceBuffer> staging =
      create_frame_buffer(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  if (!staging) return staging.error();
  std::memset(staging->mapped, 0, static_cast<std::size_t>(size));
  if (!bytes.empty()) std::memcpy(staging->mapped, bytes.data(), bytes.size());
  if (Status s = flush_for_device_read(context.device(), *staging); !s) return s.error();
  Result<DeviceBuffer> buffer =
      create_buffer(context, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                    VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0, false);
  if (!buffer) return buffer.error();

  const Status copied = submit_once(context, [&](VkCommandBuffer commands) {
    const VkBufferCopy region{0, 0, size};
    vkCmdCopyBuffer(commands, staging->buffer.get(), buffer->buffer.get(), 1, &region);
    // Later submissions read the buffer as vertices, indices or storage.
    VkMemoryBarrier2 barrier = vk_struct<VkMemoryBarrier2>(VK_STRUCTURE_TYPE_MEMORY_BARRIER_2);
    barrier.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    barrier.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    barrier.dstStageMask =
        VK_PIPELINE_STAGE_2_VERTEX_INPUT_BIT | VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT;
    barrier.dstAccessMask = VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_INDEX_READ_BIT |
                            VK_ACCESS_2_SHADER_STORAGE_READ_BIT;
    VkDependencyInfo dependency = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(commands, &dependency);
  });
  if (!copied) return copied.error();
  return std::move(*buffer);
}

Status submit_once(const VulkanContext& context,
                   const std::function<void(VkCommandBuffer)>& record) {
  const VkDevice device = context.device();
  Result<VkCommandBuffer> allocated = context.allocate_command_buffer();
  if (!allocated) return allocated.error();
  VkCommandBuffer commands = *allocated;
  struct FreeCommands {
    VkDevice device;
    VkCommandPool pool;
    VkCommandBuffer commands;
    ~FreeCommands() { vkFreeCommandBuffers(device, pool, 1, &commands); }
  } free_commands{device, context.command_pool(), commands};
  VkCommandBufferBeginInfo begin =
      vk_struct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  if (VkResult r = vkBeginCommandBuffer(commands, &begin); r != VK_SUCCESS) {
    return vk_error("vkBeginCommandBuffer", r);
  }
  record(commands);
  if (VkResult r = vkEndCommandBuffer(commands); r != VK_SUCCESS) {
    return vk_error("vkEndCommandBuffer", r);
  }
  VkCommandBufferSubmitInfo command_info =
      vk_struct<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
  command_info.commandBuffer = commands;
  VkSubmitInfo2 submit = vk_struct<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &command_info;
  if (VkResult r = vkQueueSubmit2(context.graphics_queue(), 1, &submit, VK_NULL_HANDLE);
      r != VK_SUCCESS) {
    return vk_error("vkQueueSubmit2", r);
  }
  if (VkResult r = vkQueueWaitIdle(context.graphics_queue()); r != VK_SUCCESS) {
    return vk_error("vkQueueWaitIdle", r);
  }
  return Status::success();
}

}  // namespace tutti::render
