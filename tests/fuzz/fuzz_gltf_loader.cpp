// SPDX-License-Identifier: MIT
// Any bytes as .glb or .gltf: the loader returns a model or a one-line error naming the file.
// Accepted models are posed (rest pose, world and joint matrices, every vertex deformed) so the
// indices the loader promised to have checked are exercised too.
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include <tutti/model/model_asset.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tutti::model;
  auto asset = load_model_from_memory(std::span<const std::uint8_t>(data, size), "fuzz.glb");
  if (!asset) {
    const std::string& message = asset.error().message;
    if (message.rfind("fuzz.glb: ", 0) != 0 || message.find('\n') != std::string::npos) {
      std::abort();
    }
    return 0;
  }
  const ModelPose pose = rest_pose(*asset);
  if (pose.morph_weights.size() != asset->morph_weight_count()) std::abort();
  std::vector<glm::mat4> world(asset->nodes.size());
  compute_world_matrices(*asset, pose, glm::mat4(1.0f), world);
  for (std::size_t s = 0; s < asset->skins.size(); ++s) {
    std::vector<glm::mat4> joints(asset->skins[s].joints.size());
    compute_joint_matrices(*asset, static_cast<int>(s), world, joints);
  }
  for (std::size_t n = 0; n < asset->nodes.size(); ++n) {
    const Node& node = asset->nodes[n];
    if (node.parent >= static_cast<int>(n)) std::abort();  // parents first
    if (node.mesh < 0) continue;
    const Mesh& mesh = asset->meshes[static_cast<std::size_t>(node.mesh)];
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const Primitive& primitive = mesh.primitives[p];
      for (std::uint32_t i = 0; i < primitive.index_count; ++i) {
        const std::uint32_t v = asset->indices[primitive.first_index + i];
        if (v >= primitive.vertex_count) std::abort();
        (void)deform_vertex(*asset, pose, world, static_cast<int>(n), static_cast<int>(p), v);
      }
    }
  }
  return 0;
}
