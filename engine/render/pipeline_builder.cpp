// SPDX-License-Identifier: MIT
#include <tutti/render/pipeline_builder.hpp>

#include <string>

#include <tutti/render/vk_result.hpp>

namespace tutti::render {

Result<DeviceHandle<VkShaderModule>> create_shader_module(VkDevice device,
                                                          std::span<const std::uint32_t> spirv) {
  // Hot-reloaded code comes from outside the build: refuse what is not SPIR-V before the driver
  // sees it (a header is 5 words, the magic number first).
  constexpr std::uint32_t kSpirvMagic = 0x07230203;
  if (spirv.size() < 5 || spirv[0] != kSpirvMagic) {
    return Error{"shader module: not SPIR-V (" + std::to_string(spirv.size()) +
                 " words, no SPIR-V magic number)"};
  }
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

Result<DeviceHandle<VkPipeline>> create_graphics_pipeline(VkDevice device,
                                                          const PipelineDescription& description) {
  Result<DeviceHandle<VkShaderModule>> vert =
      create_shader_module(device, description.vertex_spirv);
  if (!vert) return vert.error();
  DeviceHandle<VkShaderModule> frag;
  if (!description.fragment_spirv.empty()) {
    Result<DeviceHandle<VkShaderModule>> made =
        create_shader_module(device, description.fragment_spirv);
    if (!made) return made.error();
    frag = std::move(*made);
  }
  VkPipelineShaderStageCreateInfo stages[2] = {
      vk_struct<VkPipelineShaderStageCreateInfo>(
          VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO),
      vk_struct<VkPipelineShaderStageCreateInfo>(
          VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO)};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vert->get();
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = frag.get();
  std::vector<VkSpecializationMapEntry> entries;
  for (std::uint32_t i = 0; i < description.fragment_constants.size(); ++i) {
    entries.push_back({i, i * 4u, 4u});
  }
  VkSpecializationInfo specialization{};
  specialization.mapEntryCount = static_cast<std::uint32_t>(entries.size());
  specialization.pMapEntries = entries.data();
  specialization.dataSize = description.fragment_constants.size() * 4u;
  specialization.pData = description.fragment_constants.data();
  if (!entries.empty()) stages[1].pSpecializationInfo = &specialization;
  stages[1].pName = "main";

  VkPipelineVertexInputStateCreateInfo vertex_input =
      vk_struct<VkPipelineVertexInputStateCreateInfo>(
          VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
  vertex_input.vertexBindingDescriptionCount =
      static_cast<std::uint32_t>(description.bindings.size());
  vertex_input.pVertexBindingDescriptions = description.bindings.data();
  vertex_input.vertexAttributeDescriptionCount =
      static_cast<std::uint32_t>(description.attributes.size());
  vertex_input.pVertexAttributeDescriptions = description.attributes.data();

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
  raster.depthBiasEnable = description.depth_bias ? VK_TRUE : VK_FALSE;

  VkPipelineMultisampleStateCreateInfo multisample =
      vk_struct<VkPipelineMultisampleStateCreateInfo>(
          VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
  multisample.rasterizationSamples = description.samples;

  VkPipelineDepthStencilStateCreateInfo depth = vk_struct<VkPipelineDepthStencilStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = description.alpha_blend ? VK_FALSE : VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;

  const bool has_color = description.color_format != VK_FORMAT_UNDEFINED;
  VkPipelineColorBlendAttachmentState blend_attachment{};
  blend_attachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                    VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  if (description.alpha_blend) {
    blend_attachment.blendEnable = VK_TRUE;
    blend_attachment.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
    blend_attachment.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend_attachment.colorBlendOp = VK_BLEND_OP_ADD;
    blend_attachment.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    blend_attachment.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    blend_attachment.alphaBlendOp = VK_BLEND_OP_ADD;
  }
  VkPipelineColorBlendStateCreateInfo blend = vk_struct<VkPipelineColorBlendStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
  blend.attachmentCount = has_color ? 1 : 0;
  blend.pAttachments = &blend_attachment;

  std::vector<VkDynamicState> dynamic_states = {VK_DYNAMIC_STATE_VIEWPORT,
                                                VK_DYNAMIC_STATE_SCISSOR};
  if (description.depth_bias) dynamic_states.push_back(VK_DYNAMIC_STATE_DEPTH_BIAS);
  VkPipelineDynamicStateCreateInfo dynamic = vk_struct<VkPipelineDynamicStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO);
  dynamic.dynamicStateCount = static_cast<std::uint32_t>(dynamic_states.size());
  dynamic.pDynamicStates = dynamic_states.data();

  VkPipelineRenderingCreateInfo rendering =
      vk_struct<VkPipelineRenderingCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
  rendering.colorAttachmentCount = has_color ? 1 : 0;
  rendering.pColorAttachmentFormats = has_color ? &description.color_format : nullptr;
  rendering.depthAttachmentFormat = description.depth_format;

  VkGraphicsPipelineCreateInfo info =
      vk_struct<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
  info.pNext = &rendering;
  info.stageCount = frag ? 2 : 1;
  info.pStages = stages;
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = has_color ? &blend : nullptr;
  info.pDynamicState = &dynamic;
  info.layout = description.layout;
  VkPipeline handle = VK_NULL_HANDLE;
  if (VkResult r = vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &handle);
      r != VK_SUCCESS) {
    return vk_error("vkCreateGraphicsPipelines", r);
  }
  return DeviceHandle<VkPipeline>(device, handle, vkDestroyPipeline);
}

}  // namespace tutti::render
