// SPDX-License-Identifier: MIT
#pragma once
// VulkanContext: instance, optional validation layer with a message log, physical device
// selection, logical device, one graphics queue and a command pool (Filament's VulkanContext;
// vk-bootstrap's selection rules). Vulkan 1.3 with dynamic rendering and synchronization2.
//
// Device selection: VulkanContextOptions::device empty → the best device by type
// (discrete > integrated > virtual > CPU; ties keep enumeration order); all digits → that index
// in list_vulkan_devices() order; anything else → the first device whose name contains it
// (case-insensitive), e.g. "llvmpipe". Devices below Vulkan 1.3 or without a graphics queue or
// dynamic rendering are never chosen.
//
// Not copyable or movable (the debug messenger points at the context's log); create() hands out
// a unique_ptr. Everything made from the context must be destroyed before it.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/render/device_memory.hpp>

namespace tutti::render {

// Every validation-layer message of severity warning or error, in arrival order. Thread-safe:
// the layer may call from any thread. Shared so a test can read messages emitted while the
// context is being destroyed (e.g. objects leaked at vkDestroyDevice).
class ValidationLog {
 public:
  void add(std::string message);
  std::vector<std::string> messages() const;
  std::size_t size() const;

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> messages_;
};

struct VulkanContextOptions {
  bool validation = false;  // enable VK_LAYER_KHRONOS_validation; an error if it is not installed
  // With validation: also check barriers and hazards (the layer's synchronization validation).
  // Slower; the tests turn it on.
  bool synchronization_validation = false;
  std::string device;  // "" (best), an index ("0") or a name substring ("llvmpipe")
  std::string application_name = "tutti";

  // For presenting to a window (window.hpp's require_presentation() fills all three).
  // Instance extensions to enable besides the debug ones, e.g. VK_KHR_surface and
  // VK_KHR_xcb_surface (glfwGetRequiredInstanceExtensions); an error naming them if missing.
  std::vector<std::string> instance_extensions;
  // Enable VK_KHR_swapchain; devices without it are not usable.
  bool swapchain = false;
  // When set, the graphics queue family must also be able to present: only families for which
  // this returns true are considered, and devices without one are not usable.
  std::function<bool(VkInstance, VkPhysicalDevice, std::uint32_t queue_family)> can_present;
};

// One enumerated physical device, as list_vulkan_devices() reports it.
struct VulkanDeviceInfo {
  std::uint32_t index = 0;  // enumeration order, what VulkanContextOptions::device="N" picks
  std::string name;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  std::uint32_t api_version = 0;
  bool usable = false;  // Vulkan >= 1.3, graphics queue, dynamic rendering (+ what the
                        // options ask for: swap chain, presentation)
};

// Human name of a device type: "discrete", "integrated", "virtual", "cpu", "other".
const char* device_type_name(VkPhysicalDeviceType type);

class VulkanContext {
 public:
  static Result<std::unique_ptr<VulkanContext>> create(const VulkanContextOptions& options);
  ~VulkanContext();

  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical_device() const { return physical_device_; }
  VkDevice device() const { return device_; }
  VkQueue graphics_queue() const { return graphics_queue_; }
  std::uint32_t graphics_queue_family() const { return graphics_queue_family_; }
  // Created with RESET_COMMAND_BUFFER; use from one thread at a time.
  VkCommandPool command_pool() const { return command_pool_; }
  const VulkanDeviceInfo& device_info() const { return device_info_; }
  bool validation_enabled() const { return validation_; }
  // Whether VK_KHR_swapchain is enabled (VulkanContextOptions::swapchain).
  bool swapchain_enabled() const { return swapchain_; }
  // Empty log when validation is off.
  std::shared_ptr<const ValidationLog> validation_log() const { return log_; }

  Status wait_idle() const;

  // A primary command buffer from command_pool(); the caller frees it (vkFreeCommandBuffers).
  Result<VkCommandBuffer> allocate_command_buffer() const;
  // A fence owned by the returned handle; `signaled` = created signalled.
  Result<DeviceHandle<VkFence>> create_fence(bool signaled) const;

 private:
  VulkanContext() = default;

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue graphics_queue_ = VK_NULL_HANDLE;
  std::uint32_t graphics_queue_family_ = 0;
  VkCommandPool command_pool_ = VK_NULL_HANDLE;
  VulkanDeviceInfo device_info_;
  bool validation_ = false;
  bool swapchain_ = false;
  std::shared_ptr<ValidationLog> log_ = std::make_shared<ValidationLog>();
};

// The physical devices a plain (no-layer) instance enumerates; for `--device` help and errors.
Result<std::vector<VulkanDeviceInfo>> list_vulkan_devices();

}  // namespace tutti::render
