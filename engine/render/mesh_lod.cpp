// SPDX-License-Identifier: MIT
#include <tutti/render/mesh_lod.hpp>

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace tutti::render {
namespace {

constexpr float kTargetError = 0.02f;  // of the primitive's extent
constexpr double kMinReduction = 0.7;  // a level must drop at least 30 % of the triangles

// The skin bound to `mesh` (the first node drawing it with a skin), or -1.
int skin_of_mesh(const model::ModelAsset& asset, std::size_t mesh) {
  for (const model::Node& node : asset.nodes) {
    if (node.mesh == static_cast<int>(mesh) && node.skin >= 0) return node.skin;
  }
  return -1;
}

void add_levels(const model::ModelAsset& asset, const model::Primitive& primitive, MeshLods& out,
                PrimitiveLods& lods) {
  if (primitive.index_count == 0) return;
  const model::Vertex* vertices = asset.vertices.data() + primitive.first_vertex;
  const unsigned int* source = asset.indices.data() + primitive.first_index;
  const float* positions = &vertices[0].position.x;
  constexpr std::size_t kStride = sizeof(model::Vertex);

  std::vector<unsigned int> level(primitive.index_count);
  meshopt_optimizeVertexCache(level.data(), source, primitive.index_count, primitive.vertex_count);
  const float scale = meshopt_simplifyScale(positions, primitive.vertex_count, kStride);
  std::vector<unsigned int> coarser(primitive.index_count);
  float error = 0.0f;
  for (;;) {
    LodLevel& entry = lods.levels[lods.level_count++];
    entry.first_index = static_cast<std::uint32_t>(out.indices.size());
    entry.index_count = static_cast<std::uint32_t>(level.size());
    entry.error = error * scale;
    out.indices.insert(out.indices.end(), level.begin(), level.end());
    if (lods.level_count == PrimitiveLods::kMaxLevels) break;

    const std::size_t target = (level.size() / 2) / 3 * 3;
    float level_error = 0.0f;
    // Always from level 0, so errors do not compound.
    const std::size_t count = meshopt_simplify(
        coarser.data(), out.indices.data() + lods.levels[0].first_index, lods.levels[0].index_count,
        positions, primitive.vertex_count, kStride, target, kTargetError, 0, &level_error);
    if (count == 0 ||
        static_cast<double>(count) > kMinReduction * static_cast<double>(level.size())) {
      break;
    }
    level.assign(coarser.begin(), coarser.begin() + static_cast<std::ptrdiff_t>(count));
    meshopt_optimizeVertexCache(level.data(), level.data(), level.size(), primitive.vertex_count);
    error = std::max(error, level_error);
  }
}

void add_bounds(const model::ModelAsset& asset, const model::Mesh& mesh,
                const model::Primitive& primitive, int skin, PrimitiveLods& lods) {
  const std::size_t targets = mesh.target_names.size();
  glm::vec3 low(0.0f);
  glm::vec3 high(0.0f);
  for (std::uint32_t v = 0; v < primitive.vertex_count; ++v) {
    const glm::vec3 p = asset.vertices[primitive.first_vertex + v].position;
    glm::vec3 reach(0.0f);
    for (std::size_t k = 0; k < targets; ++k) {
      reach +=
          glm::abs(asset.morph_deltas[primitive.first_morph_delta + k * primitive.vertex_count + v]
                       .position);
    }
    low = v == 0 ? p - reach : glm::min(low, p - reach);
    high = v == 0 ? p + reach : glm::max(high, p + reach);
  }
  lods.center = 0.5f * (low + high);
  lods.radius = 0.5f * glm::length(high - low);
  if (skin < 0) return;

  const model::Skin& s = asset.skins[static_cast<std::size_t>(skin)];
  std::vector<glm::vec3> joint_positions;
  for (const glm::mat4& inverse_bind : s.inverse_bind) {
    joint_positions.emplace_back(glm::inverse(inverse_bind)[3]);
  }
  std::vector<char> used(s.joints.size(), 0);
  float padding = 0.0f;
  for (std::uint32_t v = 0; v < primitive.vertex_count; ++v) {
    const model::Vertex& vertex = asset.vertices[primitive.first_vertex + v];
    for (int k = 0; k < 4; ++k) {
      if (vertex.weights[k] <= 0.0f || vertex.joints[k] >= s.joints.size()) continue;
      const std::uint32_t j = vertex.joints[k];
      used[j] = 1;
      float reach = glm::length(vertex.position - joint_positions[j]);
      for (std::size_t t = 0; t < targets; ++t) {
        reach += glm::length(
            asset.morph_deltas[primitive.first_morph_delta + t * primitive.vertex_count + v]
                .position);
      }
      padding = std::max(padding, reach);
    }
  }
  for (std::uint32_t j = 0; j < used.size(); ++j) {
    if (!used[j]) continue;
    lods.joints.push_back(j);
  }
  lods.joint_padding = padding;
}

float max_axis_scale(const glm::mat4& m) {
  return std::max(
      {glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])), glm::length(glm::vec3(m[2]))});
}

}  // namespace

BoundingSphere rigid_world_bound(const PrimitiveLods& lods, const glm::mat4& node_world) {
  BoundingSphere bound;
  bound.scale = max_axis_scale(node_world);
  bound.center = glm::vec3(node_world * glm::vec4(lods.center, 1.0f));
  bound.radius = lods.radius * bound.scale;
  return bound;
}

// The box of the posed joints the primitive uses, padded by the farthest a vertex lies from
// its joints times the joints' scale.
BoundingSphere skinned_world_bound(const PrimitiveLods& lods, const model::Skin& skin,
                                   std::span<const glm::mat4> world,
                                   std::span<const glm::mat4> joint_matrices) {
  glm::vec3 low(0.0f);
  glm::vec3 high(0.0f);
  float scale = 0.0f;
  for (std::size_t k = 0; k < lods.joints.size(); ++k) {
    const std::uint32_t j = lods.joints[k];
    const glm::vec3 p(world[static_cast<std::size_t>(skin.joints[j])][3]);
    low = k == 0 ? p : glm::min(low, p);
    high = k == 0 ? p : glm::max(high, p);
    scale = std::max(scale, max_axis_scale(joint_matrices[j]));
  }
  BoundingSphere bound;
  bound.scale = scale;
  bound.center = 0.5f * (low + high);
  bound.radius = 0.5f * glm::length(high - low) + lods.joint_padding * scale;
  return bound;
}

MeshLods build_mesh_lods(const model::ModelAsset& asset) {
  MeshLods out;
  out.indices.reserve(asset.indices.size() * 2);
  for (std::size_t m = 0; m < asset.meshes.size(); ++m) {
    const model::Mesh& mesh = asset.meshes[m];
    out.first_primitive.push_back(static_cast<std::uint32_t>(out.primitives.size()));
    const int skin = skin_of_mesh(asset, m);
    for (const model::Primitive& primitive : mesh.primitives) {
      PrimitiveLods lods;
      add_levels(asset, primitive, out, lods);
      add_bounds(asset, mesh, primitive, skin, lods);
      out.primitives.push_back(std::move(lods));
    }
  }
  return out;
}

}  // namespace tutti::render
