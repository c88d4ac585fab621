// SPDX-License-Identifier: MIT
// Rest pose, node and joint matrices, and the CPU reference of the skinning vertex shader.
#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include <tutti/model/model_asset.hpp>

namespace tutti::model {

ModelPose rest_pose(const ModelAsset& asset) {
  ModelPose pose;
  pose.local.reserve(asset.nodes.size());
  for (const Node& node : asset.nodes) pose.local.push_back(node.rest);
  pose.first_morph_weight.reserve(asset.meshes.size());
  for (const Mesh& mesh : asset.meshes) {
    pose.first_morph_weight.push_back(static_cast<std::uint32_t>(pose.morph_weights.size()));
    pose.morph_weights.insert(pose.morph_weights.end(), mesh.default_weights.begin(),
                              mesh.default_weights.end());
  }
  return pose;
}

glm::mat4 to_matrix(const NodeTransform& transform) {
  glm::mat4 m = glm::mat4_cast(transform.rotation);
  m[0] *= transform.scale.x;
  m[1] *= transform.scale.y;
  m[2] *= transform.scale.z;
  m[3] = glm::vec4(transform.translation, 1.0f);
  return m;
}

void compute_world_matrices(const ModelAsset& asset, const ModelPose& pose,
                            const glm::mat4& root_world, std::span<glm::mat4> world) {
  const std::size_t n = std::min({asset.nodes.size(), pose.local.size(), world.size()});
  for (std::size_t i = 0; i < n; ++i) {
    const int parent = asset.nodes[i].parent;
    // Parents come first (the loader guarantees it), so world[parent] is already final.
    const glm::mat4& base = (parent >= 0 && static_cast<std::size_t>(parent) < i)
                                ? world[static_cast<std::size_t>(parent)]
                                : root_world;
    world[i] = base * to_matrix(pose.local[i]);
  }
}

void compute_joint_matrices(const ModelAsset& asset, int skin, std::span<const glm::mat4> world,
                            std::span<glm::mat4> joint_matrices) {
  if (skin < 0 || static_cast<std::size_t>(skin) >= asset.skins.size()) return;
  const Skin& s = asset.skins[static_cast<std::size_t>(skin)];
  const std::size_t n = std::min(s.joints.size(), joint_matrices.size());
  for (std::size_t j = 0; j < n; ++j) {
    const auto node = static_cast<std::size_t>(s.joints[j]);
    joint_matrices[j] = (node < world.size() ? world[node] : glm::mat4(1.0f)) * s.inverse_bind[j];
  }
}

SkinnedVertex deform_vertex(const ModelAsset& asset, const ModelPose& pose,
                            std::span<const glm::mat4> world, int node, int primitive,
                            std::uint32_t vertex) {
  SkinnedVertex out{glm::vec3(0.0f), glm::vec3(0.0f)};
  if (node < 0 || static_cast<std::size_t>(node) >= asset.nodes.size() ||
      static_cast<std::size_t>(node) >= world.size()) {
    return out;
  }
  const Node& n = asset.nodes[static_cast<std::size_t>(node)];
  if (n.mesh < 0) return out;
  const auto mesh_index = static_cast<std::size_t>(n.mesh);
  const Mesh& mesh = asset.meshes[mesh_index];
  if (primitive < 0 || static_cast<std::size_t>(primitive) >= mesh.primitives.size()) return out;
  const Primitive& p = mesh.primitives[static_cast<std::size_t>(primitive)];
  if (vertex >= p.vertex_count) return out;
  const Vertex& v = asset.vertices[p.first_vertex + vertex];

  // Morph targets first (mesh space), then skinning or the node's matrix.
  glm::vec3 position = v.position;
  glm::vec3 normal = v.normal;
  const std::size_t targets = mesh.default_weights.size();
  if (targets > 0 && mesh_index < pose.first_morph_weight.size()) {
    const std::size_t first_weight = pose.first_morph_weight[mesh_index];
    for (std::size_t k = 0; k < targets && first_weight + k < pose.morph_weights.size(); ++k) {
      const float w = pose.morph_weights[first_weight + k];
      if (w == 0.0f) continue;
      const MorphDelta& d = asset.morph_deltas[p.first_morph_delta + k * p.vertex_count + vertex];
      position += w * d.position;
      normal += w * d.normal;
    }
  }

  glm::mat4 m = world[static_cast<std::size_t>(node)];
  if (n.skin >= 0) {
    const Skin& skin = asset.skins[static_cast<std::size_t>(n.skin)];
    m = glm::mat4(0.0f);
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t j = v.joints[i];
      if (v.weights[i] == 0.0f || j >= skin.joints.size()) continue;
      const auto joint_node = static_cast<std::size_t>(skin.joints[j]);
      const glm::mat4 joint_world = joint_node < world.size() ? world[joint_node] : glm::mat4(1.0f);
      m += v.weights[i] * (joint_world * skin.inverse_bind[j]);
    }
  }
  out.position = glm::vec3(m * glm::vec4(position, 1.0f));
  const glm::vec3 transformed = glm::transpose(glm::inverse(glm::mat3(m))) * normal;
  const float length = glm::length(transformed);
  out.normal = length > 0.0f ? transformed / length : transformed;
  return out;
}

}  // namespace tutti::model
