// SPDX-License-Identifier: MIT
#pragma once
// MaterialTable: every material of the models a renderer draws, on the device — its textures
// (base colour, metallic-roughness, normal, occlusion, emissive: RGBA8 images with mip levels
// made on the CPU, one sampler per glTF sampler state), its factors, UV sets and
// KHR_texture_transform in a uniform block — as one descriptor set each (set 1 of the lit
// pipelines, shaders/material.glsl). A slot without a texture reads a 1×1 neutral one (white;
// a flat normal), so the shader has no branch on presence.
//
//   auto table = MaterialTable::create(ctx, models);
//   VkDescriptorSet set = table->set(model, primitive.material);  // -1: the default material

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/render/device_memory.hpp>
#include <tutti/render/vulkan_context.hpp>

namespace tutti::render {

class MaterialTable {
 public:
  // Texture slots, in binding order.
  static constexpr std::uint32_t kSlots = 5;

  static Result<std::unique_ptr<MaterialTable>> create(
      VulkanContext& context, std::span<const model::ModelAsset* const> models);
  ~MaterialTable();
  MaterialTable(const MaterialTable&) = delete;
  MaterialTable& operator=(const MaterialTable&) = delete;

  VkDescriptorSetLayout layout() const { return layout_.get(); }
  // The set of `material` of model `model`; the default material's for -1 or out of range.
  VkDescriptorSet set(std::size_t model, int material) const;
  std::size_t texture_count() const { return textures_.size(); }

 private:
  struct Texture {
    DeviceHandle<VkImage> image;
    DeviceHandle<VkDeviceMemory> memory;
    DeviceHandle<VkImageView> view;
  };
  MaterialTable() = default;

  DeviceHandle<VkDescriptorSetLayout> layout_;
  DeviceHandle<VkDescriptorPool> pool_;
  std::vector<Texture> textures_;  // 0: white, 1: flat normal, then every model image
  std::vector<DeviceHandle<VkSampler>> samplers_;
  DeviceBuffer uniforms_;
  VkDescriptorSet default_set_ = VK_NULL_HANDLE;
  std::vector<std::vector<VkDescriptorSet>> sets_;  // [model][material]
};

}  // namespace tutti::render
