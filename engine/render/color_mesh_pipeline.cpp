// SPDX-License-Identifier: MIT
#include <tutti/render/color_mesh_pipeline.hpp>

#include <cstddef>
#include <cstring>
#include <string>

#include <tutti/render/pipeline_builder.hpp>
#include <tutti/render/shaders.hpp>
#include <tutti/render/vk_result.hpp>

namespace tutti::render {

Result<ColorMesh> ColorMesh::create(VulkanContext& context, std::span<const ColorVertex> vertices) {
  if (vertices.empty() || vertices.size() % 3 != 0) {
    return Error{"colour mesh: " + std::to_string(vertices.size()) +
                 " vertices is not a positive multiple of 3"};
  }
  ColorMesh mesh;
  Result<DeviceBuffer> buffer =
      create_host_buffer(context.physical_device(), context.device(), vertices.size_bytes(),
                         VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  if (!buffer) return buffer.error();
  mesh.buffer_ = std::move(*buffer);
  std::memcpy(mesh.buffer_.mapped, vertices.data(), vertices.size_bytes());
  if (!mesh.buffer_.coherent) {
    VkMappedMemoryRange range =
        vk_struct<VkMappedMemoryRange>(VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE);
    range.memory = mesh.buffer_.memory.get();
    range.size = VK_WHOLE_SIZE;
    if (VkResult r = vkFlushMappedMemoryRanges(context.device(), 1, &range); r != VK_SUCCESS) {
      return vk_error("vkFlushMappedMemoryRanges", r);
    }
  }
  mesh.vertex_count_ = static_cast<std::uint32_t>(vertices.size());
  return mesh;
}

Result<std::unique_ptr<ColorMeshPipeline>> ColorMeshPipeline::create(
    VulkanContext& context, VkFormat color_format, VkFormat depth_format,
    VkSampleCountFlagBits samples) {
  const VkDevice device = context.device();
  std::unique_ptr<ColorMeshPipeline> pipeline(new ColorMeshPipeline());

  VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4)};
  VkPipelineLayoutCreateInfo layout_info =
      vk_struct<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  layout_info.pushConstantRangeCount = 1;
  layout_info.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  if (VkResult r = vkCreatePipelineLayout(device, &layout_info, nullptr, &layout);
      r != VK_SUCCESS) {
    return vk_error("vkCreatePipelineLayout", r);
  }
  pipeline->layout_ = DeviceHandle<VkPipelineLayout>(device, layout, vkDestroyPipelineLayout);

  PipelineDescription description;
  description.vertex_spirv = shaders::color_mesh_vert();
  description.fragment_spirv = shaders::color_mesh_frag();
  description.bindings = {{0, sizeof(ColorVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  description.attributes = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT,
       static_cast<std::uint32_t>(offsetof(ColorVertex, position))},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<std::uint32_t>(offsetof(ColorVertex, color))},
  };
  description.color_format = color_format;
  description.depth_format = depth_format;
  description.samples = samples;
  description.layout = layout;
  Result<DeviceHandle<VkPipeline>> made = create_graphics_pipeline(device, description);
  if (!made) return made.error();
  pipeline->pipeline_ = std::move(*made);
  return pipeline;
}

void ColorMeshPipeline::draw(VkCommandBuffer commands, const ColorMesh& mesh,
                             const glm::mat4& mvp) const {
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_.get());
  vkCmdPushConstants(commands, layout_.get(), VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4),
                     &mvp);
  const VkBuffer buffer = mesh.buffer();
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(commands, 0, 1, &buffer, &offset);
  vkCmdDraw(commands, mesh.vertex_count(), 1, 0, 0);
}

}  // namespace tutti::render
