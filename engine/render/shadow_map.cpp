// SPDX-License-Identifier: MIT
#include <tutti/render/shadow_map.hpp>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include <tutti/render/image_barrier.hpp>
#include <tutti/render/vk_result.hpp>

namespace tutti::render {

glm::mat4 fit_directional_shadow(const glm::vec3& direction, const glm::vec3& center,
                                 float radius) {
  const glm::vec3 d = glm::normalize(direction);
  const glm::vec3 up = std::abs(d.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  const glm::vec3 eye = center - d * (2.0f * radius);
  const glm::mat4 view = glm::lookAt(eye, center, up);
  const glm::mat4 projection = glm::ortho(-radius, radius, -radius, radius, radius, 3.0f * radius);
  return projection * view;
}

Result<std::unique_ptr<ShadowMap>> ShadowMap::create(VulkanContext& context, std::uint32_t size) {
  if (size < 256 || size > 8192) {
    return Error{"shadow map size " + std::to_string(size) + ": must be in [256, 8192]"};
  }
  std::unique_ptr<ShadowMap> map(new ShadowMap());
  Result<DeviceImage> image =
      create_image(context.physical_device(), context.device(), kFormat, {size, size},
                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                   VK_IMAGE_ASPECT_DEPTH_BIT);
  if (!image) return image.error();
  map->image_ = std::move(*image);

  VkSamplerCreateInfo info = vk_struct<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
  info.magFilter = VK_FILTER_LINEAR;
  info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
  info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
  info.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;  // outside the map: lit
  info.compareEnable = VK_TRUE;
  info.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
  info.maxLod = 0.0f;
  VkSampler sampler = VK_NULL_HANDLE;
  if (VkResult r = vkCreateSampler(context.device(), &info, nullptr, &sampler); r != VK_SUCCESS) {
    return vk_error("vkCreateSampler", r);
  }
  map->sampler_ = DeviceHandle<VkSampler>(context.device(), sampler, vkDestroySampler);
  return map;
}

void ShadowMap::begin(VkCommandBuffer commands) const {
  // The previous frame's lit pass sampled the map; its contents are redrawn from scratch.
  record_image_barriers(
      commands,
      {image_barrier(image_.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT,
                     VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE,
                     VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                         VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                     VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                         VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                     VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL)});
  VkRenderingAttachmentInfo depth =
      vk_struct<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
  depth.imageView = image_.view.get();
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  depth.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo rendering = vk_struct<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
  rendering.renderArea = {{0, 0}, image_.extent};
  rendering.layerCount = 1;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(commands, &rendering);
  const float side = static_cast<float>(image_.extent.width);
  const VkViewport viewport{0.0f, 0.0f, side, side, 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, image_.extent};
  vkCmdSetViewport(commands, 0, 1, &viewport);
  vkCmdSetScissor(commands, 0, 1, &scissor);
  // Slope-scaled bias against acne on surfaces the light grazes.
  vkCmdSetDepthBias(commands, 1.25f, 0.0f, 1.75f);
}

void ShadowMap::end(VkCommandBuffer commands) const {
  vkCmdEndRendering(commands);
  record_image_barriers(commands, {image_barrier(image_.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT,
                                                 VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                                                 VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                                                 VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                                 VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                                                 VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)});
}

}  // namespace tutti::render
