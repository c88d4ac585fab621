// SPDX-License-Identifier: MIT
#include <tutti/model/world_matrices_below.hpp>

#include <algorithm>
#include <cstddef>

namespace tutti::model {
namespace {

// Whether node j lies below `top` (or is it). Parents come before their children (the loader
// guarantees it), so the walk up stops as soon as it passes above `top`'s index.
bool below(const ModelAsset& asset, std::size_t j, std::size_t top) {
  while (j > top) {
    const int parent = asset.nodes[j].parent;
    if (parent < 0 || static_cast<std::size_t>(parent) >= j) return false;
    j = static_cast<std::size_t>(parent);
  }
  return j == top;
}

}  // namespace

void update_world_matrices_below(const ModelAsset& asset, const ModelPose& pose,
                                 const glm::mat4& root_world, int node, std::span<glm::mat4> world) {
  const std::size_t n = std::min({asset.nodes.size(), pose.local.size(), world.size()});
  if (node < 0 || static_cast<std::size_t>(node) >= n) return;
  const auto top = static_cast<std::size_t>(node);
  // In index order, as compute_world_matrices: each parent is final before its children.
  for (std::size_t i = top; i < n; ++i) {
    if (!below(asset, i, top)) continue;
    const int parent = asset.nodes[i].parent;
    const glm::mat4& base = (parent >= 0 && static_cast<std::size_t>(parent) < i)
                                ? world[static_cast<std::size_t>(parent)]
                                : root_world;
    world[i] = base * to_matrix(pose.local[i]);
  }
}

}  // namespace tutti::model
