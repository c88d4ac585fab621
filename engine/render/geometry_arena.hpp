// SPDX-License-Identifier: MIT
#pragma once
// GeometryArena: the vertices, indices and morph deltas of every model a renderer draws, in three
// device-local buffers (one vertex buffer binding, one index buffer, one storage buffer), so a
// frame binds geometry once. Built once from ModelAssets; models are identified by their index
// in the span given to create(). The index buffer holds every level of detail (mesh_lod.hpp):
// a level's indices start at range(model).first_index + level.first_index.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/render/device_memory.hpp>
#include <tutti/render/mesh_lod.hpp>
#include <tutti/render/vulkan_context.hpp>

namespace tutti::render {

class GeometryArena {
 public:
  // Where one model's data starts in the shared buffers.
  struct ModelRange {
    std::uint32_t first_vertex = 0;
    std::uint32_t first_index = 0;
    std::uint32_t first_morph_delta = 0;  // in MorphDelta units
  };

  // An error when the models hold more than 2^31 vertices, indices or deltas in all.
  static Result<std::unique_ptr<GeometryArena>> create(
      VulkanContext& context, std::span<const model::ModelAsset* const> models);

  const ModelRange& range(std::size_t model) const { return ranges_[model]; }
  const MeshLods& lods(std::size_t model) const { return lods_[model]; }
  std::size_t model_count() const { return ranges_.size(); }
  VkBuffer vertices() const { return vertices_.buffer.get(); }
  VkBuffer indices() const { return indices_.buffer.get(); }
  VkBuffer morph_deltas() const { return morph_deltas_.buffer.get(); }
  VkDeviceSize morph_deltas_bytes() const { return morph_deltas_.size_bytes; }

 private:
  GeometryArena() = default;
  std::vector<ModelRange> ranges_;
  std::vector<MeshLods> lods_;
  DeviceBuffer vertices_;
  DeviceBuffer indices_;
  DeviceBuffer morph_deltas_;
};

}  // namespace tutti::render
