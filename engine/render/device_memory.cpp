// SPDX-License-Identifier: MIT
#include <tutti/render/device_memory.hpp>

#include <string>
#include <utility>

#include <tutti/render/vk_result.hpp>

namespace tutti::render {
namespace {

Result<DeviceHandle<VkDeviceMemory>> allocate_memory(VkDevice device,
                                                     const VkMemoryRequirements& requirements,
                                                     std::uint32_t type) {
  VkMemoryAllocateInfo allocate =
      vk_struct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  allocate.allocationSize = requirements.size;
  allocate.memoryTypeIndex = type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  if (VkResult r = vkAllocateMemory(device, &allocate, nullptr, &memory); r != VK_SUCCESS) {
    return vk_error("vkAllocateMemory", r);
  }
  return DeviceHandle<VkDeviceMemory>(device, memory, vkFreeMemory);
}

}  // namespace

Result<std::uint32_t> find_memory_type(VkPhysicalDevice physical_device, std::uint32_t type_bits,
                                       VkMemoryPropertyFlags required,
                                       VkMemoryPropertyFlags preferred) {
  VkPhysicalDeviceMemoryProperties properties;
  vkGetPhysicalDeviceMemoryProperties(physical_device, &properties);
  for (VkMemoryPropertyFlags wanted : {required | preferred, required}) {
    for (std::uint32_t i = 0; i < properties.memoryTypeCount; ++i) {
      const bool allowed = (type_bits & (1u << i)) != 0;
      if (allowed && (properties.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
    }
  }
  return Error{"no Vulkan memory type with properties 0x" + std::to_string(required) +
               " for type bits " + std::to_string(type_bits)};
}

Result<DeviceBuffer> create_buffer(VkPhysicalDevice physical_device, VkDevice device,
                                   VkDeviceSize size_bytes, VkBufferUsageFlags usage,
                                   VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred,
                                   bool map) {
  DeviceBuffer out;
  out.size_bytes = size_bytes;
  VkBufferCreateInfo info = vk_struct<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  info.size = size_bytes;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  if (VkResult r = vkCreateBuffer(device, &info, nullptr, &buffer); r != VK_SUCCESS) {
    return vk_error("vkCreateBuffer", r);
  }
  out.buffer = DeviceHandle<VkBuffer>(device, buffer, vkDestroyBuffer);

  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(device, buffer, &requirements);
  Result<std::uint32_t> type =
      find_memory_type(physical_device, requirements.memoryTypeBits, required, preferred);
  if (!type) return type.error();
  VkPhysicalDeviceMemoryProperties properties;
  vkGetPhysicalDeviceMemoryProperties(physical_device, &properties);
  out.coherent =
      (properties.memoryTypes[*type].propertyFlags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;

  Result<DeviceHandle<VkDeviceMemory>> allocated = allocate_memory(device, requirements, *type);
  if (!allocated) return allocated.error();
  out.memory = std::move(*allocated);
  VkDeviceMemory memory = out.memory.get();
  if (VkResult r = vkBindBufferMemory(device, buffer, memory, 0); r != VK_SUCCESS) {
    return vk_error("vkBindBufferMemory", r);
  }
  // Unmapped implicitly by vkFreeMemory.
  if (map) {
    if (VkResult r = vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &out.mapped);
        r != VK_SUCCESS) {
      return vk_error("vkMapMemory", r);
    }
  }
  return out;
}

Result<DeviceBuffer> create_host_buffer(VkPhysicalDevice physical_device, VkDevice device,
                                        VkDeviceSize size_bytes, VkBufferUsageFlags usage) {
  return create_buffer(physical_device, device, size_bytes, usage,
                       VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT, VK_MEMORY_PROPERTY_HOST_CACHED_BIT,
                       true);
}

Result<DeviceImage> create_image(VkPhysicalDevice physical_device, VkDevice device, VkFormat format,
                                 VkExtent2D extent, VkImageUsageFlags usage,
                                 VkImageAspectFlags aspect, VkSampleCountFlagBits samples) {
  DeviceImage out;
  out.format = format;
  out.extent = extent;
  VkImageCreateInfo info = vk_struct<VkImageCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO);
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {extent.width, extent.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  if (VkResult r = vkCreateImage(device, &info, nullptr, &image); r != VK_SUCCESS) {
    return vk_error("vkCreateImage", r);
  }
  out.image = DeviceHandle<VkImage>(device, image, vkDestroyImage);

  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(device, image, &requirements);
  const VkMemoryPropertyFlags lazily = (usage & VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT) != 0
                                           ? VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT
                                           : 0;
  Result<std::uint32_t> type = find_memory_type(physical_device, requirements.memoryTypeBits,
                                                VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, lazily);
  if (!type) return type.error();
  Result<DeviceHandle<VkDeviceMemory>> allocated = allocate_memory(device, requirements, *type);
  if (!allocated) return allocated.error();
  out.memory = std::move(*allocated);
  VkDeviceMemory memory = out.memory.get();
  if (VkResult r = vkBindImageMemory(device, image, memory, 0); r != VK_SUCCESS) {
    return vk_error("vkBindImageMemory", r);
  }

  VkImageViewCreateInfo view_info =
      vk_struct<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
  view_info.image = image;
  view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view_info.format = format;
  view_info.subresourceRange = {aspect, 0, 1, 0, 1};
  VkImageView view = VK_NULL_HANDLE;
  if (VkResult r = vkCreateImageView(device, &view_info, nullptr, &view); r != VK_SUCCESS) {
    return vk_error("vkCreateImageView", r);
  }
  out.view = DeviceHandle<VkImageView>(device, view, vkDestroyImageView);
  return out;
}

VkFormat choose_depth_format(VkPhysicalDevice physical_device) {
  for (VkFormat format : {VK_FORMAT_D32_SFLOAT, VK_FORMAT_D16_UNORM}) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(physical_device, format, &properties);
    if (properties.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) {
      return format;
    }
  }
  return VK_FORMAT_D16_UNORM;
}

Status invalidate_for_host_read(VkDevice device, const DeviceBuffer& buffer) {
  if (buffer.coherent) return Status::success();
  VkMappedMemoryRange range = vk_struct<VkMappedMemoryRange>(VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE);
  range.memory = buffer.memory.get();
  range.offset = 0;
  range.size = VK_WHOLE_SIZE;
  return vk_check("vkInvalidateMappedMemoryRanges",
                  vkInvalidateMappedMemoryRanges(device, 1, &range));
}

}  // namespace tutti::render
