// Users' characters without mapping files: Blender-made rigs (tests/data/characters/
// make_fixtures.py) named the Unreal way in centimetres and as VRM 1.0 play a trumpet and a
// trombone when the scene names the model file itself; heads and torsos stay clear of the hands.
// A model that is not a humanoid, and a model given for the pianist's hands, are one-line errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

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
