// SPDX-License-Identifier: MIT
#pragma once
// A user asset mapping file (`*.mapping.json`, format in scene/README.md): lets a scene use
// the user's own glTF character, hands or instrument (e.g. a rig exported from a DCC tool) by
// naming which of its nodes plays each tutti role ("hips" -> "mixamorig:Hips") and which morph
// targets drive the mouth, plus the transform that brings the model into tutti's metres, +Y up,
// facing +Z.
//
// Validated here: keys, the kind, every role name (unknown roles are errors listing the known
// ones), the required roles of the kind, scale and rotation ranges, the model's extension. Not
// checked here: that the model file exists and has these nodes (done when the model is loaded).

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/scene/scene.hpp>

namespace tutti::scene {

enum class AssetKind { character, hand, trumpet, trombone };

std::string_view asset_kind_name(AssetKind kind);

struct AssetMapping {
  std::string source;           // mapping file name, for messages
  std::filesystem::path model;  // .glb or .gltf, resolved against the mapping file's folder
  AssetKind kind = AssetKind::character;
  double scale = 1.0;  // model units -> metres, (0, 1000]
  Vec3 rotation_deg;   // applied to the model root: about X, then Y, then Z
  Vec3 translation_m;  // applied after the rotation
  // Which of the three the file gives: a character's mapping only overrides what tutti
  // recognises by itself (stage/model_binding.hpp), the units and facing included.
  bool scale_given = false, rotation_given = false, translation_given = false;
  // role -> node name in the model, sorted by role; every role is one of node_roles(kind).
  std::vector<std::pair<std::string, std::string>> nodes;
  // role -> morph target name, sorted by role; every role is one of morph_roles(kind).
  std::vector<std::pair<std::string, std::string>> morphs;

  // The node name mapped to `role`, "" if unmapped.
  std::string_view node(std::string_view role) const;
  std::string_view morph(std::string_view role) const;
};

// Every node role of a kind, in documentation order (character: hips .. foot_r, the 30 finger
// joints thumb_1_l .. little_3_r, the attach points mouth, grip_l, grip_r).
std::span<const std::string_view> node_roles(AssetKind kind);
// The roles a mapping of this kind must name (a character's: the roles it must end up with once
// its mapping overrides what was recognised; its file may name none).
std::span<const std::string_view> required_node_roles(AssetKind kind);
// Morph-target roles ("tension", "open" for a character; none for the other kinds).
std::span<const std::string_view> morph_roles(AssetKind kind);

// The mapping as a file's JSON (what load_asset_mapping reads back), `model` written as given.
nlohmann::ordered_json asset_mapping_document(const AssetMapping& mapping, const std::string& model,
                                              const std::string& description);

// Errors: one line, "FILE: /json/path: reason" (missing file and bad JSON as load_scene).
Result<AssetMapping> load_asset_mapping(const std::filesystem::path& path);
Result<AssetMapping> parse_asset_mapping(const nlohmann::json& document,
                                         const std::string& file_name,
                                         const std::filesystem::path& base_dir);

}  // namespace tutti::scene
