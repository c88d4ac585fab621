// SPDX-License-Identifier: MIT
#include <tutti/model/model_asset.hpp>

namespace tutti::model {

int ModelAsset::find_node(std::string_view name) const {
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::size_t ModelAsset::morph_weight_count() const {
  std::size_t count = 0;
  for (const Mesh& mesh : meshes) count += mesh.default_weights.size();
  return count;
}

}  // namespace tutti::model
