#include <tutti/stage/model_binding.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <vector>

namespace tutti::stage {
namespace {

glm::mat4 mapping_correction(const scene::AssetMapping& mapping) {
  const auto f = [](double v) { return static_cast<float>(v); };
  glm::mat4 m = glm::translate(glm::mat4(1.0f),
                               glm::vec3(f(mapping.translation_m.x), f(mapping.translation_m.y),
                                         f(mapping.translation_m.z)));
  m = glm::rotate(m, glm::radians(f(mapping.rotation_deg.z)), glm::vec3(0, 0, 1));
  m = glm::rotate(m, glm::radians(f(mapping.rotation_deg.y)), glm::vec3(0, 1, 0));
  m = glm::rotate(m, glm::radians(f(mapping.rotation_deg.x)), glm::vec3(1, 0, 0));
  return glm::scale(m, glm::vec3(f(mapping.scale)));
}

}  // namespace

Result<MappedModel> load_mapped(StageBuilder& builder, const std::filesystem::path& mapping_file,
                                const std::string& generated_file) {
  MappedModel out;
  if (mapping_file.empty()) {
    auto model = builder.generated_model(generated_file);
    if (!model) return model.error();
    out.model = *model;
    return out;
  }
  auto mapping = scene::load_asset_mapping(mapping_file);
  if (!mapping) return mapping.error();
  auto model = builder.user_model(mapping->model);
  if (!model) return model.error();
  out.model = *model;
  out.correction = mapping_correction(*mapping);
  out.mapping = std::move(*mapping);
  return out;
}

Result<int> find_role(const model::ModelAsset& asset, const MappedModel& m, std::string_view role) {
  const std::string name = m.node_name(role);
  if (name.empty()) return -1;
  const int node = asset.find_node(name);
  if (node < 0 && m.mapping) {
    return Error{m.mapping->source + ": node \"" + name + "\" for \"" + std::string(role) +
                 "\" is not in " + m.mapping->model.filename().string()};
  }
  return node;
}

glm::vec3 local_axis(const model::ModelAsset& asset, int node, const glm::mat4& correction,
                     const glm::vec3& tutti_direction) {
  if (node < 0) return tutti_direction;
  std::vector<glm::mat4> world(asset.nodes.size());
  model::compute_world_matrices(asset, model::rest_pose(asset), correction, world);
  const int parent = asset.nodes[static_cast<std::size_t>(node)].parent;
  const glm::mat3 frame =
      parent >= 0 ? glm::mat3(world[static_cast<std::size_t>(parent)]) : glm::mat3(correction);
  return glm::inverse(frame) * tutti_direction;
}

int morph_index(const model::ModelAsset& asset, const std::string& name) {
  if (name.empty()) return -1;
  std::size_t base = 0;
  for (const model::Mesh& mesh : asset.meshes) {
    for (std::size_t k = 0; k < mesh.target_names.size(); ++k) {
      if (mesh.target_names[k] == name) return static_cast<int>(base + k);
    }
    base += mesh.target_names.size();
  }
  return -1;
}

glm::mat4 placement_matrix(const scene::Vec3& position, double facing_deg) {
  glm::mat4 m = glm::translate(
      glm::mat4(1.0f), glm::vec3(static_cast<float>(position.x), static_cast<float>(position.y),
                                 static_cast<float>(position.z)));
  return glm::rotate(m, glm::radians(static_cast<float>(facing_deg)), glm::vec3(0, 1, 0));
}

}  // namespace tutti::stage
