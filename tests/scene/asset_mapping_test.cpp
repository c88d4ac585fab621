// SPDX-License-Identifier: MIT
#include <tutti/scene/asset_mapping.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <string>

#include <tutti/brass/brass_asset_kinds.hpp>

#include "scene_test_support.hpp"

namespace tutti::scene {
namespace {

using brass::kBrassAssetKinds;
using nlohmann::json;
using test::scenes_dir;
using test::ScratchDir;

bool has(std::span<const std::string_view> roles, std::string_view role) {
  return std::find(roles.begin(), roles.end(), role) != roles.end();
}

TEST(AssetMappingRoles, TheDocumentedNames) {
  const auto character = character_kind().node_roles;
  EXPECT_EQ(character.size(), 19u + 30u + 3u);
  EXPECT_EQ(character.front(), "hips");
  for (const char* role :
       {"spine", "chest", "neck", "head", "shoulder_l", "upper_arm_r", "forearm_l", "hand_r",
        "thigh_l", "shin_r", "foot_l", "thumb_1_l", "index_2_l", "middle_3_r", "ring_1_r",
        "little_3_r", "mouth", "grip_l", "grip_r"}) {
    EXPECT_TRUE(has(character, role)) << role;
  }
  EXPECT_FALSE(has(character, "little_4_r"));
  EXPECT_EQ(brass::trumpet_kind().node_roles.size(), 6u);
  EXPECT_TRUE(has(brass::trumpet_kind().node_roles, "valve_3"));
  EXPECT_EQ(brass::trombone_kind().node_roles.size(), 5u);
  EXPECT_TRUE(has(brass::trombone_kind().node_roles, "bell_section"));
  EXPECT_EQ(hand_kind().node_roles.size(), 4u + 30u);
  EXPECT_EQ(hand_kind().required_node_roles.size(), 2u + 30u);
  EXPECT_EQ(character_kind().morph_roles.size(), 2u);
  EXPECT_TRUE(brass::trumpet_kind().morph_roles.empty());
  for (const AssetKind* kind :
       {&character_kind(), &hand_kind(), &brass::trumpet_kind(), &brass::trombone_kind()}) {
    for (std::string_view role : kind->required_node_roles) {
      EXPECT_TRUE(has(kind->node_roles, role)) << role;
    }
  }
}

// The scene knows the body's kinds only; a family's kinds are known where it is registered.
TEST(AssetMappingKinds, AnInstrumentKindIsKnownOnlyWhereAFamilyGivesIt) {
  const json document = json::parse(R"({"model": "drum.glb", "kind": "snare",
    "nodes": {"head": "DrumHead"}})");
  auto unknown = parse_asset_mapping(document, "m.json", "/assets");
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.error().message, "m.json: /kind: must be one of character, hand");
  constexpr std::array<std::string_view, 2> roles{"head", "rim"};
  constexpr std::array<std::string_view, 1> required{"head"};
  const std::array<AssetKind, 1> kinds{AssetKind{"snare", roles, required, {}, false}};
  auto known = parse_asset_mapping(document, "m.json", "/assets", kinds);
  ASSERT_TRUE(known.ok()) << known.error().message;
  EXPECT_EQ(known->kind, "snare");
  EXPECT_EQ(known->node("head"), "DrumHead");
  const json no_head = json::parse(R"({"model": "drum.glb", "kind": "snare", "nodes": {"rim": "R"}})");
  auto missing = parse_asset_mapping(no_head, "m.json", "/assets", kinds);
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().message,
            "m.json: /nodes: missing role \"head\" (required for a snare: head)");
}

TEST(AssetMapping, TheExampleLoads) {
  const auto path = scenes_dir() / "examples/mixamo_character.mapping.json";
  auto mapping = load_asset_mapping(path);
  ASSERT_TRUE(mapping.ok()) << mapping.error().message;
  EXPECT_EQ(mapping->source, "mixamo_character.mapping.json");
  EXPECT_EQ(mapping->kind, kCharacterKind);
  EXPECT_EQ(mapping->model, scenes_dir() / "examples/mixamo_character.glb");
  EXPECT_DOUBLE_EQ(mapping->scale, 0.01);
  EXPECT_EQ(mapping->node("hips"), "mixamorig:Hips");
  EXPECT_EQ(mapping->node("little_3_r"), "mixamorig:RightHandPinky3");
  EXPECT_EQ(mapping->node("grip_l"), "");  // left out in the example
  EXPECT_EQ(mapping->morph("open"), "jawOpen");
  EXPECT_EQ(mapping->nodes.size(), 19u + 30u + 1u);
  EXPECT_TRUE(std::is_sorted(mapping->nodes.begin(), mapping->nodes.end()));
}

json trumpet() {
  return json::parse(R"({"model": "horn.gltf", "kind": "trumpet",
    "nodes": {"valve_1": "V1", "valve_2": "V2", "valve_3": "V3", "mouthpiece": "MP"}})");
}

std::string mapping_error_of(const json& document) {
  auto mapping = parse_asset_mapping(document, "m.json", "/assets", kBrassAssetKinds);
  if (mapping.ok()) return "(loaded)";
  return mapping.error().message;
}

TEST(AssetMappingErrors, TheValidBaseLoads) {
  auto mapping = parse_asset_mapping(trumpet(), "m.json", "/assets", kBrassAssetKinds);
  ASSERT_TRUE(mapping.ok()) << mapping.error().message;
  EXPECT_EQ(mapping->model, std::filesystem::path("/assets/horn.gltf"));
  EXPECT_EQ(mapping->node("valve_2"), "V2");
  EXPECT_EQ(mapping->scale, 1.0);
}

TEST(AssetMappingErrors, UnknownRoleListsTheKnownOnes) {
  json doc = trumpet();
  doc["nodes"]["valve_4"] = "V4";
  EXPECT_EQ(mapping_error_of(doc),
            "m.json: /nodes/valve_4: unknown role (known for a trumpet: valve_1, valve_2, "
            "valve_3, mouthpiece, grip_left, grip_right)");
  doc = trumpet();
  doc["morphs"] = {{"open", "jawOpen"}};
  EXPECT_EQ(mapping_error_of(doc), "m.json: /morphs/open: unknown role (a trumpet has none)");
}

TEST(AssetMappingErrors, MissingRequiredRole) {
  json doc = json::parse(R"({"model": "bone.glb", "kind": "trombone",
    "nodes": {"mouthpiece": "MP", "bell_section": "Bell"}})");
  EXPECT_EQ(mapping_error_of(doc),
            "m.json: /nodes: missing role \"slide\" (required for a trombone: slide, mouthpiece)");
}

TEST(AssetMappingErrors, BadValues) {
  json doc = trumpet();
  doc["kind"] = "horn";
  EXPECT_EQ(mapping_error_of(doc),
            "m.json: /kind: must be one of character, hand, trumpet, trombone");
  doc = trumpet();
  doc["model"] = "horn.fbx";
  EXPECT_EQ(mapping_error_of(doc), "m.json: /model: expected a .glb, .gltf or .vrm file");
  doc = trumpet();
  doc["scale"] = 0;
  EXPECT_EQ(mapping_error_of(doc), "m.json: /scale: must be positive");
  doc["scale"] = 5000;
  EXPECT_EQ(mapping_error_of(doc), "m.json: /scale: must be in [0, 1000]");
  doc = trumpet();
  doc["rotation_deg"] = {0, 720, 0};
  EXPECT_EQ(mapping_error_of(doc), "m.json: /rotation_deg/1: must be in [-360, 360]");
  doc = trumpet();
  doc["nodes"]["valve_1"] = "";
  EXPECT_EQ(mapping_error_of(doc), "m.json: /nodes/valve_1: must not be empty");
  doc = trumpet();
  doc["nodes"]["valve_1"] = 1;
  EXPECT_EQ(mapping_error_of(doc), "m.json: /nodes/valve_1: expected a string");
  doc = trumpet();
  doc["bones"] = json::object();
  EXPECT_EQ(mapping_error_of(doc), "m.json: /bones: unknown key");
  doc = trumpet();
  doc.erase("nodes");
  EXPECT_EQ(mapping_error_of(doc), "m.json: /nodes: missing");
}

TEST(AssetMappingErrors, BadFiles) {
  ScratchDir dir;
  auto mapping = load_asset_mapping(dir.write("bad.mapping.json", "{\"model\": "));
  ASSERT_FALSE(mapping.ok());
  EXPECT_EQ(mapping.error().message.rfind("bad.mapping.json: not valid JSON (at line 1", 0), 0u)
      << mapping.error().message;
  EXPECT_EQ(mapping.error().message.find('\n'), std::string::npos);
  mapping = load_asset_mapping(dir.path() / "none.mapping.json");
  ASSERT_FALSE(mapping.ok());
  EXPECT_EQ(mapping.error().message,
            (dir.path() / "none.mapping.json").string() + ": no such file");
}

}  // namespace
}  // namespace tutti::scene
