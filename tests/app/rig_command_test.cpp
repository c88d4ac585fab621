// `tutti rig`: the generated performer recognised without a mapping (every role, metres, 1.75 m,
// facing +Z); the same figure packed by gltfpack; --mapping writes a file the scene loader
// accepts; a file that is not a humanoid, or not a model, is one error line with exit code 2.
#include <tutti/cli/rig_command.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include <tutti/cli/exit_codes.hpp>
#include <tutti/scene/asset_mapping.hpp>

#include "command_run.hpp"
#include "scratch_dir.hpp"

namespace tutti::app {
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

}  // namespace
}  // namespace tutti::app
