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
//
// The kinds of the body (a character, a player's hands) are the scene's own; an instrument family
// adds the kinds of its instruments (scene_section.hpp, SceneSection::asset_kinds) with their
// roles, and the loader checks a mapping file against all of them.

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

// A kind of asset and the roles a mapping of it names. The views point at storage that outlives
// every load (a family's constants).
struct AssetKind {
  std::string_view name;  // the mapping file's "kind"
  // Every node role, in documentation order.
  std::span<const std::string_view> node_roles;
  // The roles a mapping of this kind must name (a character's: the roles it must end up with
  // once its mapping overrides what was recognised; its file may name none).
  std::span<const std::string_view> required_node_roles;
  // Morph-target roles ("tension", "open" for a character).
  std::span<const std::string_view> morph_roles;
  // The stage recognises one in a model file by itself (characters, hands), so a scene may name
  // the model instead of a mapping; a mapping then overrides what was recognised.
  bool recognised_by_itself = false;
};

inline constexpr std::string_view kCharacterKind = "character";
inline constexpr std::string_view kHandKind = "hand";

// The body's kinds: a character (hips .. foot_r, the 30 finger joints thumb_1_l .. little_3_r,
// the attach points mouth, grip_l, grip_r) and a player's hands.
const AssetKind& character_kind();
const AssetKind& hand_kind();

struct AssetMapping {
  std::string source;           // mapping file name, for messages
  std::filesystem::path model;  // .glb or .gltf, resolved against the mapping file's folder
  std::string kind{kCharacterKind};  // an AssetKind's name
  double scale = 1.0;  // model units -> metres, (0, 1000]
  Vec3 rotation_deg;   // applied to the model root: about X, then Y, then Z
  Vec3 translation_m;  // applied after the rotation
  // Which of the three the file gives: a character's mapping only overrides what tutti
  // recognises by itself (stage/model_binding.hpp), the units and facing included.
  bool scale_given = false, rotation_given = false, translation_given = false;
  // role -> node name in the model, sorted by role; every role is one of the kind's node roles.
  std::vector<std::pair<std::string, std::string>> nodes;
  // role -> morph target name, sorted by role; every role is one of the kind's morph roles.
  std::vector<std::pair<std::string, std::string>> morphs;

  // The node name mapped to `role`, "" if unmapped.
  std::string_view node(std::string_view role) const;
  std::string_view morph(std::string_view role) const;
};

// The mapping as a file's JSON (what load_asset_mapping reads back), `model` written as given,
// the nodes in the kind's order.
nlohmann::ordered_json asset_mapping_document(const AssetMapping& mapping, const AssetKind& kind,
                                              const std::string& model,
                                              const std::string& description);

// A mapping file of a body kind or of one of `instrument_kinds` (the families'). Errors: one
// line, "FILE: /json/path: reason" (missing file and bad JSON as load_scene).
Result<AssetMapping> load_asset_mapping(const std::filesystem::path& path,
                                        std::span<const AssetKind> instrument_kinds = {});
Result<AssetMapping> parse_asset_mapping(const nlohmann::json& document,
                                         const std::string& file_name,
                                         const std::filesystem::path& base_dir,
                                         std::span<const AssetKind> instrument_kinds = {});

}  // namespace tutti::scene
