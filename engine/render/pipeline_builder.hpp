// SPDX-License-Identifier: MIT
#pragma once
// Graphics pipelines for dynamic rendering from a short description (vkguide's PipelineBuilder):
// the fixed-function state tutti uses everywhere (triangle lists, dynamic viewport and scissor,
// no culling, depth test LESS with writes) with the few knobs that differ between passes.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/render/device_memory.hpp>

namespace tutti::render {

Result<DeviceHandle<VkShaderModule>> create_shader_module(VkDevice device,
                                                          std::span<const std::uint32_t> spirv);

struct PipelineDescription {
  std::span<const std::uint32_t> vertex_spirv;
  std::span<const std::uint32_t> fragment_spirv;  // empty: depth-only pass
  std::vector<VkVertexInputBindingDescription> bindings;
  std::vector<VkVertexInputAttributeDescription> attributes;
  VkFormat color_format = VK_FORMAT_UNDEFINED;  // UNDEFINED: no colour attachment
  VkFormat depth_format = VK_FORMAT_UNDEFINED;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  bool depth_bias = false;  // constant + slope bias (shadow maps), set dynamically
  // Alpha blending over what is drawn (straight alpha), without writing depth: glTF BLEND.
  bool alpha_blend = false;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  // 32-bit specialization constants of the fragment shader, constant_id = index (compile-time
  // choices without a run-time branch: lavapipe runs both sides of a branch it cannot prove
  // uniform).
  std::vector<std::uint32_t> fragment_constants;
};

Result<DeviceHandle<VkPipeline>> create_graphics_pipeline(VkDevice device,
                                                          const PipelineDescription& description);

}  // namespace tutti::render
