// SPDX-License-Identifier: MIT
#pragma once
// Device-local buffers filled once through a staging buffer (static geometry), and host-visible
// buffers the CPU rewrites every frame (matrices, weights, uniforms).

#include <vulkan/vulkan.h>

#include <cstddef>
#include <functional>
#include <span>

#include <tutti/core/result.hpp>
#include <tutti/render/device_memory.hpp>
#include <tutti/render/vulkan_context.hpp>

namespace tutti::render {

// A DEVICE_LOCAL buffer with `bytes` copied in (TRANSFER_DST is added to `usage`); waits for the
// copy. An empty span still makes a 16-byte buffer, so descriptors always have something to bind.
Result<DeviceBuffer> create_device_buffer_with_data(VulkanContext& context,
                                                    std::span<const std::byte> bytes,
                                                    VkBufferUsageFlags usage);

// A persistently mapped host-visible buffer for per-frame data (host-coherent preferred).
Result<DeviceBuffer> create_frame_buffer(VulkanContext& context, VkDeviceSize size_bytes,
                                         VkBufferUsageFlags usage);

// Makes host writes to `buffer` visible to the device (no-op for coherent memory).
Status flush_for_device_read(VkDevice device, const DeviceBuffer& buffer);

// Records `record` into a one-time command buffer, submits it to the graphics queue and waits for
// it (uploads at load time: buffers, textures).
Status submit_once(const VulkanContext& context,
                   const std::function<void(VkCommandBuffer)>& record);

}  // namespace tutti::render
