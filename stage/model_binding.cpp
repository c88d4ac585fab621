// SPDX-License-Identifier: MIT
#include <tutti/stage/model_binding.hpp>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

#include <tutti/humanoid/humanoid.hpp>
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

// A character model: its humanoid recognised (engine/humanoid) into the mapping `tutti rig
// --mapping` would write, then whatever the user's mapping file (`overrides`, if any) names put
// over it: roles, morphs, and the scale, rotation and translation it gives.
Result<MappedModel> load_recognised(StageBuilder& builder, const std::filesystem::path& file,
                                    const scene::AssetMapping* overrides) {
  auto model = builder.user_model(file);
  if (!model) return model.error();
  const model::ModelAsset& asset = builder.model(*model);
  const humanoid::Humanoid h = humanoid::recognise(asset);
  const std::string source = overrides != nullptr ? overrides->source : file.filename().string();
  if (!h.problems.empty() || (overrides == nullptr && !h.playable())) {
    return Error{source + ": not a humanoid tutti can play: " + h.what_is_missing() +
                 " (tutti rig " + file.filename().string() + " shows what was recognised)"};
  }
  scene::AssetMapping mapping = recognised_character_mapping(h, asset, file);
  mapping.source = source;
  if (overrides != nullptr) {
    const auto put = [](std::vector<std::pair<std::string, std::string>>& into,
                        const std::vector<std::pair<std::string, std::string>>& from) {
      for (const auto& [role, name] : from) {
        const auto at = std::find_if(into.begin(), into.end(),
                                     [&](const auto& entry) { return entry.first == role; });
        if (at != into.end()) {
          at->second = name;
        } else {
          into.emplace_back(role, name);
        }
      }
    };
    put(mapping.nodes, overrides->nodes);
    put(mapping.morphs, overrides->morphs);
    if (overrides->scale_given) mapping.scale = overrides->scale;
    if (overrides->rotation_given) mapping.rotation_deg = overrides->rotation_deg;
    if (overrides->translation_given) mapping.translation_m = overrides->translation_m;
    std::string missing;
    for (const std::string_view role : scene::character_kind().required_node_roles) {
      if (mapping.node(role).empty()) missing += (missing.empty() ? "" : ", ") + std::string(role);
    }
    if (!missing.empty()) {
      return Error{source + ": " + file.filename().string() + " has no " + missing +
                   " that tutti recognises, and the mapping does not name them"};
    }
  }
  std::sort(mapping.nodes.begin(), mapping.nodes.end());
  std::sort(mapping.morphs.begin(), mapping.morphs.end());
  MappedModel out;
  out.model = *model;
  out.correction = mapping_correction(mapping);
  out.mapping = std::move(mapping);
  return out;
}

}  // namespace

scene::AssetMapping recognised_character_mapping(const humanoid::Humanoid& humanoid,
                                                 const model::ModelAsset& asset,
                                                 const std::filesystem::path& file) {
  scene::AssetMapping mapping;
  mapping.source = file.filename().string();
  mapping.model = file;
  mapping.kind = scene::kCharacterKind;
  mapping.scale = humanoid.metres_per_unit;
  const glm::dvec3 rotation = humanoid::rotation_to_tutti_deg(humanoid);
  mapping.rotation_deg = {rotation.x, rotation.y, rotation.z};
  for (const auto& [role, node] : humanoid.nodes) {
    if (node >= 0) mapping.nodes.emplace_back(role, asset.nodes[static_cast<std::size_t>(node)].name);
  }
  std::sort(mapping.nodes.begin(), mapping.nodes.end());
  mapping.morphs = humanoid.morphs;
  std::sort(mapping.morphs.begin(), mapping.morphs.end());
  return mapping;
}

Result<MappedModel> load_hands(StageBuilder& builder, const std::filesystem::path& file) {
  const std::string extension = file.extension().string();
  if (extension != ".glb" && extension != ".gltf" && extension != ".vrm") {
    return load_mapped(builder, file, "");
  }
  auto model = builder.user_model(file);
  if (!model) return model.error();
  const model::ModelAsset& asset = builder.model(*model);
  const humanoid::Humanoid h = humanoid::recognise(asset);
  const std::string name = file.filename().string();
  std::string missing;
  for (const std::string_view role : scene::hand_kind().required_node_roles) {
    if (h.node(role) < 0) missing += (missing.empty() ? "" : ", ") + std::string(role);
  }
  if (!missing.empty()) {
    return Error{name + ": not a pair of hands tutti can play: no " + missing + " (tutti rig " +
                 name + " shows what was recognised)"};
  }
  std::vector<glm::mat4> world(asset.nodes.size());
  model::compute_world_matrices(asset, model::rest_pose(asset), glm::mat4(1.0f), world);
  const float hand = glm::distance(glm::vec3(world[static_cast<std::size_t>(h.node("hand_l"))][3]),
                                   glm::vec3(world[static_cast<std::size_t>(h.node("middle_1_l"))][3]));
  double scale = 0.0;
  if (hand >= 5.0f && hand <= 25.0f) scale = 0.01;
  if (hand >= 0.05f && hand <= 0.25f) scale = 1.0;
  if (scale == 0.0) {
    return Error{name + ": a hand of " + std::to_string(hand) +
                 " units from wrist to middle knuckle: cannot tell its units (give a mapping "
                 "file of kind hand with a scale)"};
  }
  scene::AssetMapping mapping;
  mapping.source = name;
  mapping.model = file;
  mapping.kind = scene::kHandKind;
  mapping.scale = scale;
  for (const std::string_view role : scene::hand_kind().node_roles) {
    const int node = h.node(role);
    if (node >= 0) mapping.nodes.emplace_back(role, asset.nodes[static_cast<std::size_t>(node)].name);
  }
  std::sort(mapping.nodes.begin(), mapping.nodes.end());
  MappedModel out;
  out.model = *model;
  out.correction = mapping_correction(mapping);
  out.mapping = std::move(mapping);
  return out;
}

Result<MappedModel> load_mapped(StageBuilder& builder, const std::filesystem::path& mapping_file,
                                const std::string& generated_file,
                                std::span<const scene::AssetKind> instrument_kinds) {
  MappedModel out;
  if (mapping_file.empty()) {
    auto model = builder.generated_model(generated_file);
    if (!model) return model.error();
    out.model = *model;
    return out;
  }
  const std::string extension = mapping_file.extension().string();
  if (extension == ".glb" || extension == ".gltf" || extension == ".vrm") {
    return load_recognised(builder, mapping_file, nullptr);
  }
  auto mapping = scene::load_asset_mapping(mapping_file, instrument_kinds);
  if (!mapping) return mapping.error();
  if (mapping->kind == scene::kCharacterKind) {
    return load_recognised(builder, mapping->model, &*mapping);
  }
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
