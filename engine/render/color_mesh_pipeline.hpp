// SPDX-License-Identifier: MIT
#pragma once
// ColorMeshPipeline: triangles with a linear-RGB colour per vertex, depth-tested (LESS, writes
// depth), no culling, one push-constant MVP (column-major glm::mat4, Vulkan clip space: y down,
// depth 0..1). Built for dynamic rendering into given colour/depth formats.
//
// ColorMesh: the vertices in a host-visible vertex buffer (fine for small meshes and for the CPU
// device; a staging upload comes with real meshes).
//
// Both must be destroyed before the VulkanContext they were made from.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <span>

#include <tutti/core/result.hpp>
#include <tutti/render/device_memory.hpp>
#include <tutti/render/vulkan_context.hpp>

namespace tutti::render {

struct ColorVertex {
  glm::vec3 position;  // object space
  glm::vec3 color;     // linear RGB, 0..1
};

class ColorMesh {
 public:
  // Every three vertices make a triangle; an error when empty or not a multiple of three.
  static Result<ColorMesh> create(VulkanContext& context, std::span<const ColorVertex> vertices);
  std::uint32_t vertex_count() const { return vertex_count_; }
  VkBuffer buffer() const { return buffer_.buffer.get(); }

 private:
  DeviceBuffer buffer_;
  std::uint32_t vertex_count_ = 0;
};

class ColorMeshPipeline {
 public:
  // `samples` must match the attachments' sample count (FrameTarget::samples()).
  static Result<std::unique_ptr<ColorMeshPipeline>> create(
      VulkanContext& context, VkFormat color_format, VkFormat depth_format,
      VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT);
  ColorMeshPipeline(const ColorMeshPipeline&) = delete;
  ColorMeshPipeline& operator=(const ColorMeshPipeline&) = delete;

  // Records the draw into `commands`, which must be inside a dynamic rendering with matching
  // formats and with viewport and scissor set (OffscreenTarget::begin_frame does both).
  void draw(VkCommandBuffer commands, const ColorMesh& mesh, const glm::mat4& mvp) const;

 private:
  ColorMeshPipeline() = default;
  DeviceHandle<VkPipelineLayout> layout_;
  DeviceHandle<VkPipeline> pipeline_;
};

}  // namespace tutti::render
