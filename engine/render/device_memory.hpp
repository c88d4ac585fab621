// SPDX-License-Identifier: MIT
#pragma once
// RAII for device-owned Vulkan handles, and the few allocation helpers the renderer needs
// (vkguide's vk_images / vk_initializers split, without a general allocator yet).
//
// DeviceHandle<T> owns one handle created from a VkDevice and destroys it with the matching
// vkDestroy*/vkFree* function. The device must outlive every DeviceHandle made from it.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <utility>

#include <tutti/core/result.hpp>

namespace tutti::render {

template <typename Handle>
class DeviceHandle {
 public:
  using Destroy = void (*)(VkDevice, Handle, const VkAllocationCallbacks*);

  DeviceHandle() = default;
  DeviceHandle(VkDevice device, Handle handle, Destroy destroy)
      : device_(device), handle_(handle), destroy_(destroy) {}
  ~DeviceHandle() { reset(); }

  DeviceHandle(const DeviceHandle&) = delete;
  DeviceHandle& operator=(const DeviceHandle&) = delete;
  DeviceHandle(DeviceHandle&& other) noexcept
      : device_(other.device_),
        handle_(std::exchange(other.handle_, VK_NULL_HANDLE)),
        destroy_(other.destroy_) {}
  DeviceHandle& operator=(DeviceHandle&& other) noexcept {
    if (this != &other) {
      reset();
      device_ = other.device_;
      handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
      destroy_ = other.destroy_;
    }
    return *this;
  }

  Handle get() const { return handle_; }
  explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

  void reset() {
    if (handle_ != VK_NULL_HANDLE) destroy_(device_, handle_, nullptr);
    handle_ = VK_NULL_HANDLE;
  }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  Handle handle_ = VK_NULL_HANDLE;
  Destroy destroy_ = nullptr;
};

// A buffer with its own dedicated memory. `mapped` is non-null for host-visible buffers (kept
// mapped for the buffer's lifetime); `coherent` says whether reads need an invalidate first.
struct DeviceBuffer {
  DeviceHandle<VkBuffer> buffer;
  DeviceHandle<VkDeviceMemory> memory;
  VkDeviceSize size_bytes = 0;
  void* mapped = nullptr;
  bool coherent = true;
};

// A 2D image, its dedicated memory and a view of all of it.
struct DeviceImage {
  DeviceHandle<VkImage> image;
  DeviceHandle<VkDeviceMemory> memory;
  DeviceHandle<VkImageView> view;
  VkFormat format = VK_FORMAT_UNDEFINED;
  VkExtent2D extent{};
};

// Index of a memory type allowed by `type_bits` that has all of `required` (and, when one
// exists, also all of `preferred`); an error when none does.
Result<std::uint32_t> find_memory_type(VkPhysicalDevice physical_device, std::uint32_t type_bits,
                                       VkMemoryPropertyFlags required,
                                       VkMemoryPropertyFlags preferred = 0);

// A buffer with dedicated memory of a type that has `required` (and `preferred` when one
// exists); `map` keeps it mapped for its lifetime (host-visible memory only).
Result<DeviceBuffer> create_buffer(VkPhysicalDevice physical_device, VkDevice device,
                                   VkDeviceSize size_bytes, VkBufferUsageFlags usage,
                                   VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred,
                                   bool map);

// A host-visible buffer (host-cached preferred: the CPU reads it back), persistently mapped.
Result<DeviceBuffer> create_host_buffer(VkPhysicalDevice physical_device, VkDevice device,
                                        VkDeviceSize size_bytes, VkBufferUsageFlags usage);

// A device-local, optimal-tiling 2D image with one mip level and one layer, plus its view.
// `samples` > 1 makes a multisampled attachment (MSAA); lazily allocated memory is used when the
// usage is TRANSIENT_ATTACHMENT and the device offers it.
Result<DeviceImage> create_image(VkPhysicalDevice physical_device, VkDevice device, VkFormat format,
                                 VkExtent2D extent, VkImageUsageFlags usage,
                                 VkImageAspectFlags aspect,
                                 VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);

// The depth attachment format: D32_SFLOAT when the device supports it, else D16_UNORM (which
// every device must).
VkFormat choose_depth_format(VkPhysicalDevice physical_device);

// Makes the device's writes to `buffer` visible to the host (no-op for coherent memory).
Status invalidate_for_host_read(VkDevice device, const DeviceBuffer& buffer);

}  // namespace tutti::render
