// SPDX-License-Identifier: MIT
#pragma once
// The key light's shadow map: a square depth image rendered from the light with an orthographic
// projection fitted around a bounding sphere, then sampled with depth comparison (hardware 2x2
// filter, 3x3 taps in lit.frag).

#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>

#include <tutti/core/result.hpp>
#include <tutti/render/device_memory.hpp>
#include <tutti/render/vulkan_context.hpp>

namespace tutti::render {

// World → shadow clip space for a directional light travelling along `direction`, covering the
// sphere (center, radius) in metres. The depth range spans the sphere, so everything inside it
// casts and receives shadows.
glm::mat4 fit_directional_shadow(const glm::vec3& direction, const glm::vec3& center, float radius);

class ShadowMap {
 public:
  static constexpr VkFormat kFormat = VK_FORMAT_D32_SFLOAT;

  // size: texels per side, 256..8192.
  static Result<std::unique_ptr<ShadowMap>> create(VulkanContext& context, std::uint32_t size);

  std::uint32_t size() const { return image_.extent.width; }
  VkImageView view() const { return image_.view.get(); }
  VkSampler sampler() const { return sampler_.get(); }

  // Begins a depth-only rendering into the map (cleared to 1), viewport and scissor set, depth
  // bias set for the shadow pipeline. Outside any other rendering.
  void begin(VkCommandBuffer commands) const;
  // Ends it and makes the depth readable by fragment shaders.
  void end(VkCommandBuffer commands) const;

 private:
  ShadowMap() = default;
  DeviceImage image_;
  DeviceHandle<VkSampler> sampler_;
};

}  // namespace tutti::render
