#include "render/color_mesh_pipeline.hpp"

#include <cstddef>
#include <cstring>
#include <string>

#include "render/shaders.hpp"
#include "render/vk_result.hpp"

namespace tutti::render {
namespace {

Result<DeviceHandle<VkShaderModule>> create_shader(VkDevice device,
                                                   std::span<const std::uint32_t> spirv) {
  VkShaderModuleCreateInfo info =
      vk_struct<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
  info.codeSize = spirv.size_bytes();
  info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  if (VkResult r = vkCreateShaderModule(device, &info, nullptr, &module); r != VK_SUCCESS) {
    return vk_error("vkCreateShaderModule", r);
  }
  return DeviceHandle<VkShaderModule>(device, module, vkDestroyShaderModule);
}

}  // namespace

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

Result<std::unique_ptr<ColorMeshPipeline>> ColorMeshPipeline::create(VulkanContext& context,
                                                                     VkFormat color_format,
                                                                     VkFormat depth_format) {
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

  Result<DeviceHandle<VkShaderModule>> vert = create_shader(device, shaders::color_mesh_vert());
  if (!vert) return vert.error();
  Result<DeviceHandle<VkShaderModule>> frag = create_shader(device, shaders::color_mesh_frag());
  if (!frag) return frag.error();
  VkPipelineShaderStageCreateInfo stages[2] = {
      vk_struct<VkPipelineShaderStageCreateInfo>(
          VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO),
      vk_struct<VkPipelineShaderStageCreateInfo>(
          VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO)};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vert->get();
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = frag->get();
  stages[1].pName = "main";

  const VkVertexInputBindingDescription binding{0, sizeof(ColorVertex),
                                                VK_VERTEX_INPUT_RATE_VERTEX};
  const VkVertexInputAttributeDescription attributes[2] = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT,
       static_cast<std::uint32_t>(offsetof(ColorVertex, position))},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, static_cast<std::uint32_t>(offsetof(ColorVertex, color))},
  };
  VkPipelineVertexInputStateCreateInfo vertex_input =
      vk_struct<VkPipelineVertexInputStateCreateInfo>(
          VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
  vertex_input.vertexBindingDescriptionCount = 1;
  vertex_input.pVertexBindingDescriptions = &binding;
  vertex_input.vertexAttributeDescriptionCount = 2;
  vertex_input.pVertexAttributeDescriptions = attributes;

  VkPipelineInputAssemblyStateCreateInfo assembly =
      vk_struct<VkPipelineInputAssemblyStateCreateInfo>(
          VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;

  VkPipelineViewportStateCreateInfo viewport = vk_struct<VkPipelineViewportStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;

  VkPipelineRasterizationStateCreateInfo raster = vk_struct<VkPipelineRasterizationStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;

  VkPipelineMultisampleStateCreateInfo multisample =
      vk_struct<VkPipelineMultisampleStateCreateInfo>(
          VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

  VkPipelineDepthStencilStateCreateInfo depth = vk_struct<VkPipelineDepthStencilStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;

  VkPipelineColorBlendAttachmentState blend_attachment{};
  blend_attachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                    VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blend = vk_struct<VkPipelineColorBlendStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
  blend.attachmentCount = 1;
  blend.pAttachments = &blend_attachment;

  const VkDynamicState dynamic_states[2] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic = vk_struct<VkPipelineDynamicStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;

  VkPipelineRenderingCreateInfo rendering =
      vk_struct<VkPipelineRenderingCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachmentFormats = &color_format;
  rendering.depthAttachmentFormat = depth_format;

  VkGraphicsPipelineCreateInfo info =
      vk_struct<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
  info.pNext = &rendering;
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout;
  VkPipeline handle = VK_NULL_HANDLE;
  if (VkResult r = vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &handle);
      r != VK_SUCCESS) {
    return vk_error("vkCreateGraphicsPipelines", r);
  }
  pipeline->pipeline_ = DeviceHandle<VkPipeline>(device, handle, vkDestroyPipeline);
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
