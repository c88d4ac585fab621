// SPDX-License-Identifier: MIT
#pragma once
// Vulkan results as tutti errors (vk-bootstrap style): a failing call becomes an Error whose
// message names the call and the VkResult, e.g. "vkCreateDevice: VK_ERROR_INITIALIZATION_FAILED".

#include <vulkan/vulkan.h>

#include <string>

#include <tutti/core/result.hpp>

namespace tutti::render {

// A Vulkan info struct with its sType set and every other member zero.
template <typename T>
T vk_struct(VkStructureType type) {
  T value{};
  value.sType = type;
  return value;
}

// "VK_ERROR_OUT_OF_HOST_MEMORY", ... or "VkResult(-13)" for values this table lacks.
std::string to_string(VkResult result);

// Error{"<call>: <VkResult>"}.
Error vk_error(const char* call, VkResult result);

// Status of one call: success when result == VK_SUCCESS.
inline Status vk_check(const char* call, VkResult result) {
  if (result == VK_SUCCESS) return Status::success();
  return vk_error(call, result);
}

}  // namespace tutti::render
