// SPDX-License-Identifier: MIT
#pragma once
// Binding a model to what a family needs of it: the generated asset, whose roles are its node
// names, or a user's model through a mapping file (scene/asset_mapping.hpp: roles → the user's
// node and morph names, plus the transform into metres, +Y up, facing +Z).

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <tutti/core/result.hpp>
#include <tutti/humanoid/humanoid.hpp>
#include <tutti/model/model_asset.hpp>
#include <tutti/scene/asset_mapping.hpp>
#include <tutti/scene/scene.hpp>
#include <tutti/stage/stage_builder.hpp>

namespace tutti::stage {

struct MappedModel {
  std::uint32_t model = 0;
  glm::mat4 correction{1.0f};
  std::optional<scene::AssetMapping> mapping;

  std::string node_name(std::string_view role) const {
    return mapping ? std::string(mapping->node(role)) : std::string(role);
  }
  std::string morph_name(std::string_view role) const {
    return mapping ? std::string(mapping->morph(role)) : std::string(role);
  }
};

// The user's model named by `mapping_file`, or the generated `generated_file` when it is empty.
// A character (a model file, or a mapping file of kind character) is recognised by itself and
// the mapping file's roles, morphs, scale, rotation and translation override what was found; an
// instrument's or hand's mapping file is taken as it is, its kind one of the body's or of
// `instrument_kinds` (the calling family's).
Result<MappedModel> load_mapped(StageBuilder& builder, const std::filesystem::path& mapping_file,
                                const std::string& generated_file,
                                std::span<const scene::AssetKind> instrument_kinds = {});

// A player's hands from a user's model: a mapping file of kind hand as it is, or a model file
// whose hands and fingers are recognised by themselves (engine/humanoid); its units from the
// hands' size (a wrist to middle knuckle of 5-25 units: centimetres, of 0.05-0.25: metres).
Result<MappedModel> load_hands(StageBuilder& builder, const std::filesystem::path& file);

// What a character model given as its file stands for, and what `tutti rig --mapping` writes:
// the roles engine/humanoid recognised in `asset` (loaded from `file`) as node names, its units
// and the rotation that stands it on +Y facing +Z, its face morphs.
scene::AssetMapping recognised_character_mapping(const humanoid::Humanoid& humanoid,
                                                 const model::ModelAsset& asset,
                                                 const std::filesystem::path& file);

// The node playing `role`: -1 when unmapped or missing from a generated model; an error when a
// mapping names a node the model lacks.
Result<int> find_role(const model::ModelAsset& asset, const MappedModel& m, std::string_view role);

// Direction `tutti_direction` (model frame after the correction) in the local frame of `node`'s
// parent at rest, so a translation along it moves the node that way whatever the user's axes.
glm::vec3 local_axis(const model::ModelAsset& asset, int node, const glm::mat4& correction,
                     const glm::vec3& tutti_direction);

// Index of the morph target `name` over all meshes (ModelPose::morph_weights), -1 = none.
int morph_index(const model::ModelAsset& asset, const std::string& name);

// A seat's placement on the stage: feet at `position`, turned `facing_deg` about +Y.
glm::mat4 placement_matrix(const scene::Vec3& position, double facing_deg);

}  // namespace tutti::stage
