// SPDX-License-Identifier: MIT
#include <tutti/render/geometry_arena.hpp>

#include <glm/glm.hpp>
#include <limits>
#include <string>

#include <tutti/render/buffer_upload.hpp>

namespace tutti::render {

// The vertex input bindings in model_renderer.cpp read this layout.
static_assert(sizeof(model::Vertex) == 72);

Result<std::unique_ptr<GeometryArena>> GeometryArena::create(
    VulkanContext& context, std::span<const model::ModelAsset* const> models) {
  std::unique_ptr<GeometryArena> arena(new GeometryArena());
  std::size_t vertex_count = 0;
  std::size_t index_count = 0;
  std::size_t delta_count = 0;
  constexpr std::size_t kLimit = std::numeric_limits<std::int32_t>::max();
  for (const model::ModelAsset* asset : models) {
    arena->lods_.push_back(build_mesh_lods(*asset));
    arena->ranges_.push_back({static_cast<std::uint32_t>(vertex_count),
                              static_cast<std::uint32_t>(index_count),
                              static_cast<std::uint32_t>(delta_count)});
    vertex_count += asset->vertices.size();
    index_count += arena->lods_.back().indices.size();
    delta_count += asset->morph_deltas.size();
    if (vertex_count > kLimit || index_count > kLimit || delta_count > kLimit / 2) {
      return Error{asset->source + ": too much geometry for one renderer (" +
                   std::to_string(vertex_count) + " vertices, " + std::to_string(index_count) +
                   " indices in all)"};
    }
  }
  std::vector<model::Vertex> vertices;
  std::vector<std::uint32_t> indices;
  // The shader reads deltas as vec4 pairs (std430 has no tightly packed vec3 array).
  std::vector<glm::vec4> deltas;
  vertices.reserve(vertex_count);
  indices.reserve(index_count);
  deltas.reserve(delta_count * 2);
  for (std::size_t m = 0; m < models.size(); ++m) {
    const model::ModelAsset* asset = models[m];
    vertices.insert(vertices.end(), asset->vertices.begin(), asset->vertices.end());
    const std::vector<std::uint32_t>& lod_indices = arena->lods_[m].indices;
    indices.insert(indices.end(), lod_indices.begin(), lod_indices.end());
    for (const model::MorphDelta& d : asset->morph_deltas) {
      deltas.emplace_back(d.position, 0.0f);
      deltas.emplace_back(d.normal, 0.0f);
    }
  }
  Result<DeviceBuffer> vertex_buffer = create_device_buffer_with_data(
      context, std::as_bytes(std::span(vertices)), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  if (!vertex_buffer) return vertex_buffer.error();
  arena->vertices_ = std::move(*vertex_buffer);
  Result<DeviceBuffer> index_buffer = create_device_buffer_with_data(
      context, std::as_bytes(std::span(indices)), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  if (!index_buffer) return index_buffer.error();
  arena->indices_ = std::move(*index_buffer);
  Result<DeviceBuffer> delta_buffer = create_device_buffer_with_data(
      context, std::as_bytes(std::span(deltas)), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  if (!delta_buffer) return delta_buffer.error();
  arena->morph_deltas_ = std::move(*delta_buffer);
  return arena;
}

}  // namespace tutti::render
