// Users' characters without mapping files: Blender-made rigs (tests/data/characters/
// make_fixtures.py) named the Unreal way in centimetres and as VRM 1.0 play a trumpet and a
// trombone when the scene names the model file itself; heads and torsos stay clear of the hands.
// A model that is not a humanoid, and a model given for the pianist's hands, are one-line errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include <cmath>

#include <tutti/brass/brass_components.hpp>
#include <tutti/humanoid/humanoid.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/performance/pose_check.hpp>
#include <tutti/scene/load_scene.hpp>

#include "scratch_dir.hpp"

namespace tutti::performance {
namespace {

const std::filesystem::path kSource(TUTTI_SOURCE_DIR);

bool make_fixtures(const std::filesystem::path& dir) {
  const std::string command = "blender -b --factory-startup --python '" +
                              (kSource / "tests/data/characters/make_fixtures.py").string() +
                              "' -- '" + dir.string() + "' > /dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

nlohmann::json duo(const std::string& trumpet_character, const std::string& trombone_character) {
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(kSource / "content/scenes/quartet.json"));
  scene["music"] = (kSource / "content/music/quartet.musicxml").string();
  scene["performers"].erase(3);
  scene["performers"].erase(1);
  scene["performers"][0]["character"] = trumpet_character;
  scene["performers"][1]["character"] = trombone_character;
  return scene;
}

TEST(UserCharacter, ModelFilesPlayWithoutAMapping) {
  if (std::system("command -v blender > /dev/null 2>&1") != 0) GTEST_SKIP() << "no blender";
  test::ScratchDir dir;
  ASSERT_TRUE(make_fixtures(dir.path()));
  const std::filesystem::path file = dir.path() / "duo.json";
  std::ofstream(file) << duo("unreal_cm_t.glb", "rigify_a_vrm1.vrm").dump(1);
  auto scene = scene::load_scene(file);
  ASSERT_TRUE(scene) << scene.error().message;
  auto staged = build_stage(*scene, {});
  ASSERT_TRUE(staged) << staged.error().message;
  PoseCheckOptions options;
  options.from_s = 0.0;
  options.to_s = 6.0;
  auto report = check_pose(**staged, options);
  ASSERT_TRUE(report) << report.error().message;
  for (const char* who : {"Trumpet 1", "Trombone 1"}) {
    const std::string w = who;
    const PoseMeasure* head = report->find(w + ": hands and fingertips inside the head (depth; 0 = outside)");
    ASSERT_NE(head, nullptr) << who;
    EXPECT_EQ(head->worst(), 0.0) << who;
    const PoseMeasure* torso =
        report->find(w + ": hands, fingertips and elbows inside the torso (depth; 0 = outside)");
    ASSERT_NE(torso, nullptr) << who;
    EXPECT_EQ(torso->worst(), 0.0) << who;
  }
  const PoseMeasure* wrist =
      report->find("Trumpet 1: left hand's origin (wrist) to the valve casings' axis");
  ASSERT_NE(wrist, nullptr);
  EXPECT_LE(wrist->percentile(0.5), 60.0);
}

// The sideways sway of a player's head (standard deviation of its world x over 12 s) in the
// duo's first seat: with `character` set, a user's rig; without, tutti's performer.
double head_sway_m(const std::filesystem::path& dir, const std::string& character) {
  nlohmann::json scene = duo("", "");
  scene["performers"].erase(1);
  if (character.empty()) {
    scene["performers"][0].erase("character");
  } else {
    scene["performers"][0]["character"] = character;
  }
  const std::filesystem::path file = dir / ("sway_" + std::to_string(character.size()) + ".json");
  std::ofstream(file) << scene.dump(1);
  auto loaded = scene::load_scene(file);
  EXPECT_TRUE(loaded) << loaded.error().message;
  if (!loaded) return 0.0;
  auto staged = build_stage(*loaded, {});
  EXPECT_TRUE(staged) << staged.error().message;
  if (!staged) return 0.0;
  stage::Stage& stage = **staged;
  const ecs::Entity performer = stage.performers().at(0);
  const auto* rig = stage.world().try_get<brass_family::BrassRig>(performer);
  EXPECT_NE(rig, nullptr);
  if (rig == nullptr) return 0.0;
  double sum = 0.0, sum2 = 0.0;
  int n = 0;
  std::vector<glm::mat4> world;
  for (double t = 0.0; t < 12.0; t += 1.0 / 30.0) {
    stage.run({t, 1.0 / 30.0});
    const auto* body = stage.world().try_get<stage::PlacedModel>(rig->body);
    world.resize(body->asset->nodes.size());
    model::compute_world_matrices(*body->asset, body->pose, body->root, world);
    const double x = world[static_cast<std::size_t>(rig->body_nodes.head)][3].x;
    sum += x;
    sum2 += x * x;
    ++n;
  }
  const double mean = sum / n;
  return std::sqrt(std::max(0.0, sum2 / n - mean * mean));
}

// Body motion on user rigs: the head sways as much as tutti's performer's in the same seat
// (within 20 %, the user's rig being 2.0 m tall to the performer's 1.75 m).
TEST(UserCharacter, UserRigsSwayLikeTuttisPerformer) {
  if (std::system("command -v blender > /dev/null 2>&1") != 0) GTEST_SKIP() << "no blender";
  test::ScratchDir dir;
  ASSERT_TRUE(make_fixtures(dir.path()));
  const double own = head_sway_m(dir.path(), "");
  ASSERT_GT(own, 0.002);  // tutti's performer sways by millimetres to centimetres
  for (const char* fixture : {"unreal_cm_t.glb", "rigify_a_vrm1.vrm", "mixamo_ns_cm_a.glb"}) {
    const double theirs = head_sway_m(dir.path(), fixture);
    EXPECT_GT(theirs / own, 0.8) << fixture << ": " << theirs << " m against " << own << " m";
    EXPECT_LT(theirs / own, 1.2) << fixture << ": " << theirs << " m against " << own << " m";
  }
}

TEST(UserCharacter, NotAHumanoidAndModelHandsAreOneLineErrors) {
  test::ScratchDir dir;
  std::filesystem::copy_file(std::filesystem::path(TUTTI_PERFORMANCE_TEST_ASSET_DIR) / "trumpet.glb",
                             dir.path() / "horn_not_a_man.glb");
  const std::filesystem::path file = dir.path() / "duo.json";
  std::ofstream(file) << duo("horn_not_a_man.glb", "horn_not_a_man.glb").dump(1);
  auto scene = scene::load_scene(file);
  ASSERT_TRUE(scene) << scene.error().message;
  auto staged = build_stage(*scene, {});
  ASSERT_FALSE(staged);
  const std::string& message = staged.error().message;
  EXPECT_NE(message.find("horn_not_a_man.glb: not a humanoid tutti can play: no hips"),
            std::string::npos)
      << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);

  nlohmann::json piano = nlohmann::json::parse(std::ifstream(kSource / "content/scenes/piano.json"));
  piano["music"] = (kSource / "content/music" / piano["music"].get<std::string>()).string();
  piano["pianist"]["hands"] = "horn_not_a_man.glb";
  std::ofstream(dir.path() / "piano.json") << piano.dump(1);
  auto refused = scene::load_scene(dir.path() / "piano.json");
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().message.find("needs a mapping file"), std::string::npos)
      << refused.error().message;
}

}  // namespace
}  // namespace tutti::performance
