// SPDX-License-Identifier: MIT
// `tutti rig`: the generated performer recognised without a mapping (every role, metres, 1.75 m,
// facing +Z); the same figure packed by gltfpack; --mapping writes a file the scene loader
// accepts; a file that is not a humanoid, or not a model, and a broken rig (no skin, a loop in the
// node tree, NaN in a matrix) is one error line with exit code 2.
#include <tutti/cli/rig_command.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include <tutti/core/exit_codes.hpp>
#include <tutti/scene/asset_mapping.hpp>

#include "command_run.hpp"
#include "scratch_dir.hpp"

namespace tutti::cli {
namespace {

const std::filesystem::path kAssets(TUTTI_APP_TEST_ASSET_DIR);

TEST(RigCommand, ThePerformerIsRecognisedWithoutAMapping) {
  RigOptions o;
  o.model = kAssets / "performer.glb";
  o.json = true;
  const auto r = test::run_command(run_rig, o);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc.at("method"), "bone names and hierarchy");
  EXPECT_EQ(doc.at("nodes").size(), 49u);
  EXPECT_EQ(doc.at("nodes").at("hand_r"), "hand_r");
  EXPECT_EQ(doc.at("missing_required").size(), 0u);
  EXPECT_EQ(doc.at("metres_per_unit"), 1.0);
  EXPECT_NEAR(doc.at("height_m").get<double>(), 1.75, 0.03);
  EXPECT_NEAR(doc.at("facing")[2].get<double>(), 1.0, 1e-3);
  EXPECT_EQ(doc.at("morphs").at("open"), "open");
  // The text report names the roles and the facts.
  o.json = false;
  const auto text = test::run_command(run_rig, o);
  EXPECT_NE(text.out.find("roles: 49 of 49"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("height 1.7"), std::string::npos) << text.out;
}

TEST(RigCommand, MappingIsWrittenAndLoads) {
  test::ScratchDir dir;
  RigOptions o;
  o.model = kAssets / "performer.glb";
  o.mapping = true;
  o.output = dir.path() / "performer.mapping.json";
  const auto r = test::run_command(run_rig, o);
  ASSERT_EQ(r.code, kExitOk) << r.err;
  auto mapping = scene::load_asset_mapping(o.output);
  ASSERT_TRUE(mapping) << mapping.error().message;
  EXPECT_EQ(mapping->node("forearm_l"), "forearm_l");
  EXPECT_EQ(mapping->scale, 1.0);
  EXPECT_EQ(std::filesystem::weakly_canonical(mapping->model),
            std::filesystem::weakly_canonical(o.model));
  // Without -o: one line.
  o.output.clear();
  const auto missing = test::run_command(run_rig, o);
  EXPECT_EQ(missing.code, kExitBadInput);
  EXPECT_EQ(missing.err, "error: --mapping needs -o FILE.mapping.json\n");
}

TEST(RigCommand, NotAHumanoidOrNotAModelIsOneLine) {
  RigOptions o;
  o.model = kAssets / "trumpet.glb";
  auto r = test::run_command(run_rig, o);
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("trumpet.glb: not a humanoid tutti can play: no hips"), std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  o.model = "/nonexistent/avatar.vrm";
  r = test::run_command(run_rig, o);
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("/nonexistent/avatar.vrm"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
}

// The performer's GLB with its JSON edited (and its binary chunk patched by `patch`).
std::filesystem::path edited_performer(const std::filesystem::path& dir, const std::string& name,
                                       const std::function<void(nlohmann::json&)>& edit,
                                       const std::function<void(const nlohmann::json&, std::string&)>& patch = {}) {
  std::ifstream in(kAssets / "performer.glb", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::uint32_t json_length = 0;
  std::memcpy(&json_length, bytes.data() + 12, 4);
  nlohmann::json document = nlohmann::json::parse(bytes.substr(20, json_length));
  std::string binary = bytes.substr(20 + json_length);
  edit(document);
  if (patch) patch(document, binary);
  std::string text = document.dump();
  while (text.size() % 4 != 0) text += ' ';
  const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::string body = u32(static_cast<std::uint32_t>(text.size())) + u32(0x4E4F534Au) + text + binary;
  const std::filesystem::path out = dir / name;
  std::ofstream(out, std::ios::binary) << u32(0x46546C67u) << u32(2)
                                       << u32(static_cast<std::uint32_t>(12 + body.size())) << body;
  return out;
}

TEST(RigCommand, BrokenRigsAreOneLineNamingTheProblem) {
  test::ScratchDir dir;
  struct Case {
    std::filesystem::path file;
    std::string problem;
  };
  std::vector<Case> cases;
  cases.push_back({edited_performer(dir.path(), "no_skin.glb",
                                    [](nlohmann::json& d) {
                                      for (auto& node : d["nodes"]) node.erase("skin");
                                      d.erase("skins");
                                    }),
                   "no skin"});
  cases.push_back({edited_performer(dir.path(), "loop.glb",
                                    [](nlohmann::json& d) {
                                      const std::size_t n = d["nodes"].size();
                                      d["nodes"].push_back({{"name", "a"}, {"children", {n + 1}}});
                                      d["nodes"].push_back({{"name", "b"}, {"children", {n}}});
                                    }),
                   "a cycle in the node tree"});
  cases.push_back({edited_performer(
                       dir.path(), "nan.glb", [](nlohmann::json&) {},
                       [](const nlohmann::json& d, std::string& binary) {
                         const auto& accessor =
                             d["accessors"][d["skins"][0]["inverseBindMatrices"].get<std::size_t>()];
                         const auto& view = d["bufferViews"][accessor["bufferView"].get<std::size_t>()];
                         const std::size_t at = 8 + view.value("byteOffset", 0u) +
                                                accessor.value("byteOffset", 0u) + 13 * 4;
                         const float nan = std::nanf("");
                         std::memcpy(binary.data() + at, &nan, 4);
                       }),
                   "non-finite number (NaN or infinity)"});
  // A mapping file given where the model belongs.
  const std::filesystem::path mapping = dir.path() / "pchar.json";
  std::ofstream(mapping) << R"({"kind": "character", "model": "hero.glb"})";
  cases.push_back({mapping, "a mapping file, not a model (tutti rig reads the model it names: "
                            "hero.glb)"});
  for (const Case& c : cases) {
    RigOptions o;
    o.model = c.file;
    auto r = test::run_command(run_rig, o);
    EXPECT_EQ(r.code, kExitBadInput) << c.file;
    EXPECT_NE(r.err.find(c.file.filename().string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.problem), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
}  // namespace tutti::cli
