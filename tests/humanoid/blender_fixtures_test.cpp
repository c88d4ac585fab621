// SPDX-License-Identifier: MIT
// Characters made by third-party tools (tests/data/characters/make_fixtures.py, run here with
// Debian's Blender): Rigify's human meta-rig skinned and exported by Blender's glTF exporter,
// under the Rigify, Mixamo (namespaced, plain, prefixed) and Unreal names, in metres and in
// centimetres under a 0.01 root scale, in A- and T-pose, as VRM 1.0, and packed by gltfpack.
// Every one is recognised without a mapping: all 49 roles on the bones the names say, 2.0 m tall
// in metres (the root scale applied once), up +Y, facing +Z, the rest pose it was made in.
#include <tutti/humanoid/humanoid.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "scratch_dir.hpp"

namespace tutti::humanoid {
namespace {

// tutti's role -> the Rigify meta-rig's bone.
std::map<std::string, std::string> rigify_bones() {
  std::map<std::string, std::string> m{{"hips", "spine"},       {"spine", "spine.001"},
                                       {"chest", "spine.003"},  {"neck", "spine.004"},
                                       {"head", "spine.006"}};
  for (const char* side : {"l", "r"}) {
    const std::string x = side;
    const std::string s = x == "l" ? ".L" : ".R";
    for (const char* limb : {"shoulder", "upper_arm", "forearm", "hand", "thigh", "shin", "foot"}) {
      m[std::string(limb) + "_" + x] = limb + s;
    }
    for (int k = 1; k <= 3; ++k) {
      const std::string n = "0" + std::to_string(k);
      m["thumb_" + std::to_string(k) + "_" + x] = "thumb." + n + s;
      m["index_" + std::to_string(k) + "_" + x] = "f_index." + n + s;
      m["middle_" + std::to_string(k) + "_" + x] = "f_middle." + n + s;
      m["ring_" + std::to_string(k) + "_" + x] = "f_ring." + n + s;
      m["little_" + std::to_string(k) + "_" + x] = "f_pinky." + n + s;
    }
  }
  return m;
}

TEST(BlenderFixtures, EveryExportIsRecognisedWithoutAMapping) {
  if (std::system("command -v blender > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "no blender (Debian package blender, in scripts/packages-test.txt)";
  }
  test::ScratchDir dir;
  const std::string script = std::string(TUTTI_SOURCE_DIR) + "/tests/data/characters/make_fixtures.py";
  const std::string command = "blender -b --factory-startup --python '" + script + "' -- '" +
                              dir.path().string() + "' > '" + (dir.path() / "blender.log").string() +
                              "' 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream listing(dir.path() / "fixtures.json");
  ASSERT_TRUE(listing) << "no fixtures.json; see " << (dir.path() / "blender.log");
  nlohmann::json fixtures = nlohmann::json::parse(listing);
  ASSERT_GE(fixtures.size(), 7u);
  // One more: the Mixamo-named one packed by gltfpack (quantized, meshopt-compressed).
  if (std::system("command -v gltfpack > /dev/null 2>&1") == 0) {
    const std::string pack = "gltfpack -kn -cc -i '" + (dir.path() / "mixamo_ns_cm_a.glb").string() +
                             "' -o '" + (dir.path() / "mixamo_ns_cm_a_packed.glb").string() +
                             "' > /dev/null 2>&1";
    ASSERT_EQ(std::system(pack.c_str()), 0);
    nlohmann::json packed;
    for (const auto& f : fixtures) {
      if (f.at("file") == "mixamo_ns_cm_a.glb") packed = f;
    }
    ASSERT_FALSE(packed.is_null());
    packed["file"] = "mixamo_ns_cm_a_packed.glb";
    fixtures.push_back(packed);
  }
  const auto bones = rigify_bones();
  for (const auto& f : fixtures) {
    const std::string file = f.at("file");
    auto asset = model::load_model(dir.path() / file);
    ASSERT_TRUE(asset) << asset.error().message;
    const Humanoid h = recognise(*asset);
    EXPECT_TRUE(h.playable()) << file;
    EXPECT_TRUE(h.missing_optional.empty()) << file;
    EXPECT_EQ(h.method, f.value("vrm", false) ? "VRM 1.0 humanoid table" : "bone names and hierarchy")
        << file;
    for (const auto& [role, node] : h.nodes) {
      const std::string expected = f.at("names").at(bones.at(std::string(role)));
      ASSERT_GE(node, 0) << file << " " << role;
      EXPECT_EQ(asset->nodes[static_cast<std::size_t>(node)].name, expected) << file << " " << role;
    }
    EXPECT_EQ(h.metres_per_unit, 1.0) << file;
    EXPECT_FALSE(h.units_guessed) << file;
    EXPECT_NEAR(h.height_m, 2.0, 0.05) << file;
    EXPECT_GT(h.up.y, 0.99f) << file;
    EXPECT_GT(h.facing.z, 0.99f) << file;
    EXPECT_EQ(h.rest, f.at("pose") == "T" ? RestPose::t_pose : RestPose::a_pose) << file;
  }
}

}  // namespace
}  // namespace tutti::humanoid
