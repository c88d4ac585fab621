// SPDX-License-Identifier: MIT
#pragma once
// Levels of detail and bounds for every primitive of a model, built once when a renderer loads
// it (meshoptimizer, Debian's libmeshoptimizer-dev). lavapipe shades vertices and sets up
// triangles on the CPU, so a performer seen across the stage must not cost what a close-up costs.
//
// A coarser level is only another index list over the same vertices (meshopt_simplify keeps a
// subset of them), so skin weights and morph deltas apply unchanged. Level 0 holds every
// triangle of the file, reordered for the post-transform vertex cache.
//
// Also per primitive: a bounding sphere in mesh space (morph deltas included) for unskinned
// meshes, and for skinned ones the joints its vertices use with the farthest any vertex lies
// from such a joint in the bind pose, so a posed bound is the joints' box padded by that.

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include <tutti/model/model_asset.hpp>

namespace tutti::render {

struct LodLevel {
  std::uint32_t first_index = 0;  // into MeshLods::indices (values relative to first_vertex)
  std::uint32_t index_count = 0;
  float error = 0.0f;  // the farthest the surface moved from level 0, mesh-space metres
};

struct PrimitiveLods {
  static constexpr std::size_t kMaxLevels = 4;
  std::array<LodLevel, kMaxLevels> levels{};
  std::uint32_t level_count = 0;  // >= 1 for a primitive with triangles
  // Unskinned use: the sphere around every vertex with any morph at full weight.
  glm::vec3 center{0.0f};
  float radius = 0.0f;
  // Skinned use: indices into the skin's joint list that carry weight, and the farthest a
  // vertex lies from a joint it is bound to in the bind pose (mesh space, morphs at full
  // weight). Joint matrices that only rotate, translate and scale keep every posed vertex within
  // padding x scale of the posed joints' box.
  std::vector<std::uint32_t> joints;
  float joint_padding = 0.0f;
};

struct MeshLods {
  std::vector<std::uint32_t> indices;          // every level of every primitive
  std::vector<PrimitiveLods> primitives;       // mesh after mesh, primitive after primitive
  std::vector<std::uint32_t> first_primitive;  // per mesh: its first entry in primitives
};

struct BoundingSphere {
  glm::vec3 center{0.0f};
  float radius = 0.0f;
  float scale = 1.0f;  // mesh space -> world (the largest axis scale), for the levels' errors
};

// World bound of a primitive drawn by an unskinned node whose world matrix is `node_world`.
BoundingSphere rigid_world_bound(const PrimitiveLods& lods, const glm::mat4& node_world);
// World bound of a skinned primitive: `world` holds every node's world matrix, `joint_matrices`
// the skin's (model::compute_joint_matrices). Contains every posed vertex when the joint
// matrices rotate, translate and scale (no shear) and morph weights are in [0, 1].
BoundingSphere skinned_world_bound(const PrimitiveLods& lods, const model::Skin& skin,
                                   std::span<const glm::mat4> world,
                                   std::span<const glm::mat4> joint_matrices);

// Deterministic: the same asset gives the same levels. A level is kept only when it has at
// most 70 % of the previous level's triangles; simplification stops at 2 % of the primitive's
// extent.
MeshLods build_mesh_lods(const model::ModelAsset& asset);

}  // namespace tutti::render
