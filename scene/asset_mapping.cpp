// SPDX-License-Identifier: MIT
#include <tutti/scene/asset_mapping.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <nlohmann/json.hpp>

#include <tutti/scene/json_fields.hpp>
#include <tutti/scene/load_scene.hpp>

namespace tutti::scene {
namespace {

std::vector<std::string> finger_roles() {
  std::vector<std::string> roles;
  for (const char* side : {"l", "r"}) {
    for (const char* finger : {"thumb", "index", "middle", "ring", "little"}) {
      for (int joint = 1; joint <= 3; ++joint) {
        roles.push_back(std::string(finger) + "_" + std::to_string(joint) + "_" + side);
      }
    }
  }
  return roles;
}

struct RoleTable {
  std::vector<std::string> storage;
  std::vector<std::string_view> roles;
  std::vector<std::string_view> required;
};

RoleTable make_table(std::vector<std::string> names, std::vector<std::string> required) {
  RoleTable table;
  table.storage = std::move(names);
  for (const std::string& name : table.storage) table.roles.push_back(name);
  for (const std::string& name : required) {
    for (std::string_view role : table.roles) {
      if (role == name) table.required.push_back(role);
    }
  }
  return table;
}

const RoleTable& character_table() {
  static const RoleTable table = [] {
    std::vector<std::string> names{"hips",        "spine",      "chest",      "neck",
                                   "head",        "shoulder_l", "shoulder_r", "upper_arm_l",
                                   "upper_arm_r", "forearm_l",  "forearm_r",  "hand_l",
                                   "hand_r",      "thigh_l",    "thigh_r",    "shin_l",
                                   "shin_r",      "foot_l",     "foot_r"};
    for (std::string& finger : finger_roles()) names.push_back(std::move(finger));
    for (const char* attach : {"mouth", "grip_l", "grip_r"}) names.emplace_back(attach);
    return make_table(std::move(names), {"hips", "spine", "head", "upper_arm_l", "upper_arm_r",
                                         "forearm_l", "forearm_r", "hand_l", "hand_r"});
  }();
  return table;
}

const RoleTable& hand_table() {
  static const RoleTable table = [] {
    std::vector<std::string> names{"forearm_l", "forearm_r", "hand_l", "hand_r"};
    std::vector<std::string> required{"hand_l", "hand_r"};
    for (std::string& finger : finger_roles()) {
      required.push_back(finger);
      names.push_back(std::move(finger));
    }
    return make_table(std::move(names), std::move(required));
  }();
  return table;
}

constexpr std::array<std::string_view, 2> kCharacterMorphs{"tension", "open"};

std::string join(std::span<const std::string_view> items) {
  std::string text;
  for (std::string_view item : items) {
    if (!text.empty()) text += ", ";
    text += item;
  }
  return text;
}

std::string article(const AssetKind& kind) { return "a " + std::string(kind.name); }

// An object of role -> name strings; every role one of `known`, every name non-empty.
Result<std::vector<std::pair<std::string, std::string>>> read_roles(
    const FieldReader& reader, const nlohmann::json& object, const std::string& path,
    std::span<const std::string_view> known, const AssetKind& kind) {
  if (!object.is_object()) return reader.error(path, "expected an object");
  std::vector<std::pair<std::string, std::string>> roles;
  for (const auto& item : object.items()) {
    const std::string where = join_path(path, item.key());
    const bool is_known = std::find(known.begin(), known.end(), item.key()) != known.end();
    if (!is_known) {
      if (known.empty())
        return reader.error(where, "unknown role (" + article(kind) + " has none)");
      return reader.error(where,
                          "unknown role (known for " + article(kind) + ": " + join(known) + ")");
    }
    if (!item.value().is_string()) return reader.error(where, "expected a string");
    std::string name = item.value().get<std::string>();
    if (name.empty()) return reader.error(where, "must not be empty");
    roles.emplace_back(item.key(), std::move(name));
  }
  std::sort(roles.begin(), roles.end());
  return roles;
}

std::string_view lookup(const std::vector<std::pair<std::string, std::string>>& roles,
                        std::string_view role) {
  for (const auto& [name, value] : roles) {
    if (name == role) return value;
  }
  return {};
}

}  // namespace

const AssetKind& character_kind() {
  static const AssetKind kind{kCharacterKind, character_table().roles, character_table().required,
                              kCharacterMorphs, true};
  return kind;
}

const AssetKind& hand_kind() {
  static const AssetKind kind{kHandKind, hand_table().roles, hand_table().required, {}, true};
  return kind;
}

std::string_view AssetMapping::node(std::string_view role) const { return lookup(nodes, role); }
std::string_view AssetMapping::morph(std::string_view role) const { return lookup(morphs, role); }

Result<AssetMapping> load_asset_mapping(const std::filesystem::path& path,
                                        std::span<const AssetKind> instrument_kinds) {
  auto document = read_scene_json(path);
  if (!document) return document.error();
  return parse_asset_mapping(*document, path.filename().string(), path.parent_path(),
                             instrument_kinds);
}

Result<AssetMapping> parse_asset_mapping(const nlohmann::json& document,
                                         const std::string& file_name,
                                         const std::filesystem::path& base_dir,
                                         std::span<const AssetKind> instrument_kinds) {
  const FieldReader reader(file_name);
  if (auto ok = reader.json().check_keys(document, "",
                                         {"description", "model", "kind", "scale", "rotation_deg",
                                          "translation_m", "nodes", "morphs"});
      !ok) {
    return ok.error();
  }
  AssetMapping mapping;
  mapping.source = file_name;
  if (document.contains("description") && !document.at("description").is_string()) {
    return reader.error("/description", "expected a string");
  }

  auto model = reader.string(document, "", "model");
  if (!model) return model.error();
  std::string extension = std::filesystem::path(*model).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".glb" && extension != ".gltf" && extension != ".vrm") {
    return reader.error("/model", "expected a .glb, .gltf or .vrm file");
  }
  mapping.model = (base_dir / *model).lexically_normal();

  auto kind = reader.string(document, "", "kind");
  if (!kind) return kind.error();
  std::vector<const AssetKind*> known{&character_kind(), &hand_kind()};
  for (const AssetKind& k : instrument_kinds) known.push_back(&k);
  const AssetKind* found = nullptr;
  std::string kinds;
  for (const AssetKind* k : known) {
    kinds += (kinds.empty() ? "" : ", ") + std::string(k->name);
    if (found == nullptr && k->name == *kind) found = k;
  }
  if (found == nullptr) return reader.error("/kind", "must be one of " + kinds);
  const AssetKind& the_kind = *found;
  mapping.kind = *kind;

  auto scale = reader.number_or(document, "", "scale", 0.0, 1000.0, 1.0);
  if (!scale) return scale.error();
  if (*scale <= 0.0) return reader.error("/scale", "must be positive");
  mapping.scale = *scale;
  mapping.scale_given = document.contains("scale");
  auto rotation = reader.vec3_or(document, "", "rotation_deg", 360.0, {});
  if (!rotation) return rotation.error();
  mapping.rotation_deg = *rotation;
  mapping.rotation_given = document.contains("rotation_deg");
  auto translation = reader.vec3_or(document, "", "translation_m", 100.0, {});
  if (!translation) return translation.error();
  mapping.translation_m = *translation;
  mapping.translation_given = document.contains("translation_m");

  // A character's mapping overrides what is recognised: it may name any roles, or none.
  const bool overrides = the_kind.name == kCharacterKind;
  if (!document.contains("nodes") && !overrides) return reader.error("/nodes", "missing");
  if (document.contains("nodes")) {
    auto nodes =
        read_roles(reader, document.at("nodes"), "/nodes", the_kind.node_roles, the_kind);
    if (!nodes) return nodes.error();
    mapping.nodes = std::move(*nodes);
  }
  for (std::string_view role : the_kind.required_node_roles) {
    if (overrides) break;
    if (mapping.node(role).empty()) {
      return reader.error("/nodes", "missing role \"" + std::string(role) + "\" (required for " +
                                        article(the_kind) + ": " +
                                        join(the_kind.required_node_roles) + ")");
    }
  }
  if (document.contains("morphs")) {
    auto morphs =
        read_roles(reader, document.at("morphs"), "/morphs", the_kind.morph_roles, the_kind);
    if (!morphs) return morphs.error();
    mapping.morphs = std::move(*morphs);
  }
  return mapping;
}

nlohmann::ordered_json asset_mapping_document(const AssetMapping& mapping, const AssetKind& kind,
                                              const std::string& model,
                                              const std::string& description) {
  nlohmann::ordered_json doc;
  if (!description.empty()) doc["description"] = description;
  doc["model"] = model;
  doc["kind"] = std::string(kind.name);
  doc["scale"] = mapping.scale;
  doc["rotation_deg"] = {mapping.rotation_deg.x, mapping.rotation_deg.y, mapping.rotation_deg.z};
  if (mapping.translation_m.x != 0.0 || mapping.translation_m.y != 0.0 ||
      mapping.translation_m.z != 0.0) {
    doc["translation_m"] = {mapping.translation_m.x, mapping.translation_m.y, mapping.translation_m.z};
  }
  doc["nodes"] = nlohmann::ordered_json::object();
  for (const std::string_view role : kind.node_roles) {
    const std::string_view node = mapping.node(role);
    if (!node.empty()) doc["nodes"][std::string(role)] = std::string(node);
  }
  if (!mapping.morphs.empty()) {
    doc["morphs"] = nlohmann::ordered_json::object();
    for (const auto& [role, name] : mapping.morphs) doc["morphs"][role] = name;
  }
  return doc;
}

}  // namespace tutti::scene
