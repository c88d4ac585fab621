// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <tutti/content/json_reader.hpp>
#include <tutti/core/file_io.hpp>
#include <tutti/generator/dimensions.hpp>
#include <tutti/generator/generate.hpp>
#include <tutti/generator/piano_asset.hpp>
#include <tutti/generator/props.hpp>
#include "gltf_test_support.hpp"
#include <tutti/piano_model/keyboard.hpp>

namespace tutti::test {
namespace {

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

struct ProcessResult {
  int exit_code = -1;
  std::string stderr_text;
};

ProcessResult run_generator(const std::string& arguments, const std::filesystem::path& scratch) {
  const std::filesystem::path err = scratch / "stderr.txt";
  const std::string command =
      std::string("'") + TUTTI_CONTENT_GENERATOR + "' " + arguments + " 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  ProcessResult run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.stderr_text = read_all(err);
  return run;
}

TEST(ContentGenerator, SameInputGivesByteIdenticalFiles) {
  GeneratedAssets first("first");
  GeneratedAssets second("second");
  for (const std::string& name : content_generator::asset_file_names()) {
    const std::string a = read_all(first.dir() / name);
    const std::string b = read_all(second.dir() / name);
    ASSERT_GT(a.size(), 1000u) << name;
    EXPECT_TRUE(a == b) << name << " differs between two runs";
    // The build's own copy (the custom command) is the same file.
    EXPECT_TRUE(a == read_all(std::filesystem::path(TUTTI_ASSET_DIR) / name))
        << name << " differs from the build tree's copy";
  }
}

TEST(ContentGenerator, WritesGlbContainersWithAJsonAndABinaryChunk) {
  GeneratedAssets assets("container");
  for (const std::string& name : content_generator::asset_file_names()) {
    const std::string bytes = read_all(assets.dir() / name);
    ASSERT_GE(bytes.size(), 28u) << name;
    EXPECT_EQ(bytes.substr(0, 4), "glTF") << name;
    std::uint32_t version = 0;
    std::uint32_t length = 0;
    std::uint32_t json_length = 0;
    std::memcpy(&version, bytes.data() + 4, 4);
    std::memcpy(&length, bytes.data() + 8, 4);
    std::memcpy(&json_length, bytes.data() + 12, 4);
    EXPECT_EQ(version, 2u) << name;
    EXPECT_EQ(length, bytes.size()) << name;
    EXPECT_EQ(bytes.substr(16, 4), "JSON") << name;
    EXPECT_EQ(json_length % 4, 0u) << name;
    ASSERT_LT(20u + json_length + 8u, bytes.size()) << name;
    EXPECT_EQ(bytes.substr(20 + json_length + 4, 3), std::string("BIN")) << name;
    const std::string json = bytes.substr(20, json_length);
    EXPECT_NE(json.find("\"generator\":\"tutti\""), std::string::npos) << name;
    EXPECT_NE(json.find("\"version\":\"2.0\""), std::string::npos) << name;
  }
}

TEST(ContentGenerator, ProgramWritesEveryAsset) {
  const std::filesystem::path dir = unique_temp_path("program");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const ProcessResult run = run_generator(
      "'" + (dir / "out").string() + "' --content '" + content_dir().string() + "'", dir);
  EXPECT_EQ(run.exit_code, 0) << run.stderr_text;
  EXPECT_EQ(run.stderr_text, "");
  for (const std::string& name : content_generator::asset_file_names()) {
    const tinygltf::Model model = load_glb(dir / "out" / name);
    EXPECT_FALSE(model.nodes.empty()) << name;
  }
  std::filesystem::remove_all(dir);
}

TEST(ContentGenerator, MissingOrBrokenKeyboardIsAOneLineErrorAndExitCode2) {
  const std::filesystem::path dir = unique_temp_path("errors");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "empty");
  std::filesystem::create_directories(dir / "broken" / "piano");
  ASSERT_TRUE(write_file_atomically(dir / "broken" / "piano" / "keyboard.json",
                                    "{\"lowest_key\": 21, \"highest_key\": ")
                  .ok());
  std::filesystem::create_directories(dir / "invalid" / "piano");
  ASSERT_TRUE(write_file_atomically(dir / "invalid" / "piano" / "keyboard.json",
                                    R"({"lowest_key": 21, "highest_key": 108,
                                        "white_key_width_mm": -1, "black_key_centres_mm": {}})")
                  .ok());

  for (const char* content : {"empty", "broken", "invalid"}) {
    const ProcessResult run = run_generator(
        "'" + (dir / "out").string() + "' --content '" + (dir / content).string() + "'", dir);
    EXPECT_EQ(run.exit_code, 2) << content;
    EXPECT_EQ(run.stderr_text.rfind("error: ", 0), 0u) << run.stderr_text;
    EXPECT_NE(run.stderr_text.find("keyboard.json"), std::string::npos) << run.stderr_text;
    ASSERT_FALSE(run.stderr_text.empty());
    EXPECT_EQ(run.stderr_text.find('\n'), run.stderr_text.size() - 1) << run.stderr_text;
    EXPECT_FALSE(std::filesystem::exists(dir / "out" / "piano.glb")) << content;
  }
  // The library gives the same reason as an Error.
  const Status status = content_generator::generate_assets(dir / "invalid", dir / "out");
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("/white_key_width_mm"), std::string::npos)
      << status.error().message;

  // An output folder that cannot be created (a file is in the way).
  ASSERT_TRUE(write_file_atomically(dir / "a_file", "x").ok());
  const ProcessResult blocked = run_generator(
      "'" + (dir / "a_file").string() + "' --content '" + content_dir().string() + "'", dir);
  EXPECT_EQ(blocked.exit_code, 2);
  EXPECT_EQ(blocked.stderr_text.rfind("error: " + (dir / "a_file").string() + ": ", 0), 0u)
      << blocked.stderr_text;
  EXPECT_EQ(blocked.stderr_text.find('\n'), blocked.stderr_text.size() - 1) << blocked.stderr_text;

  const ProcessResult usage = run_generator("", dir);
  EXPECT_EQ(usage.exit_code, 2);
  EXPECT_NE(usage.stderr_text.find("missing OUT_DIR"), std::string::npos) << usage.stderr_text;
  std::filesystem::remove_all(dir);
}

// A content folder with the shipped data and a dimensions.json of our own.
std::filesystem::path content_with_dimensions(const std::filesystem::path& dir,
                                              const std::string& dimensions_json) {
  // The other inputs (piano/, instruments/, generator/hand_rig.json) as shipped.
  std::filesystem::create_directories(dir / "generator");
  std::filesystem::copy(
      content_dir() / "piano", dir / "piano",
      std::filesystem::copy_options::recursive | std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy(
      content_dir() / "instruments", dir / "instruments",
      std::filesystem::copy_options::recursive | std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(content_dir() / "generator" / "hand_rig.json",
                             dir / "generator" / "hand_rig.json",
                             std::filesystem::copy_options::overwrite_existing);
  EXPECT_TRUE(write_file_atomically(dir / "generator" / "dimensions.json", dimensions_json).ok());
  return dir;
}

TEST(ContentGenerator, DimensionsComeFromTheDataFile) {
  const std::filesystem::path dir = unique_temp_path("dimensions");
  std::filesystem::remove_all(dir);
  auto document = content::read_json_file(content_dir() / "generator" / "dimensions.json");
  ASSERT_TRUE(document.ok()) << document.error().message;
  (*document)["piano"]["key_top_above_floor_mm"] = 800.0;
  (*document)["piano"]["white_key_length_mm"] = 140.0;
  (*document)["chair"]["seat_top_mm"] = 500.0;
  (*document)["music_stand"]["hinge_height_mm"] = 1100.0;
  const auto content = content_with_dimensions(dir / "content", document->dump());
  const Status status = content_generator::generate_assets(content, dir / "out");
  ASSERT_TRUE(status.ok()) << status.error().message;

  const tinygltf::Model piano = load_glb(dir / "out" / "piano.glb");
  const int key = find_node(piano, "key_60");
  ASSERT_GE(key, 0);
  EXPECT_NEAR(world_translation(piano, key, 1), 0.800, 1e-9);
  EXPECT_NEAR(world_translation(piano, key, 2), -0.140, 1e-9);
  const tinygltf::Model chair = load_glb(dir / "out" / "chair.glb");
  const int seat = chair.nodes.at(static_cast<std::size_t>(find_node(chair, "seat"))).mesh;
  EXPECT_NEAR(position_accessor(chair, seat).maxValues[1], 0.5, 1e-6);
  const tinygltf::Model stand = load_glb(dir / "out" / "music_stand.glb");
  const auto& desk = stand.nodes.at(static_cast<std::size_t>(find_node(stand, "desk")));
  ASSERT_EQ(desk.translation.size(), 3u);
  EXPECT_NEAR(desk.translation[1], 1.1, 1e-9);
  // The shipped file and the defaults in dimensions.hpp agree.
  auto shipped =
      content_generator::AssetDimensions::load(content_dir() / "generator" / "dimensions.json");
  ASSERT_TRUE(shipped.ok()) << shipped.error().message;
  auto keyboard = piano_model::Keyboard::load(content_dir() / "piano" / "keyboard.json");
  ASSERT_TRUE(keyboard.ok()) << keyboard.error().message;
  EXPECT_TRUE(content_generator::to_glb(content_generator::build_piano(*keyboard, shipped->piano))
                  .value() ==
              content_generator::to_glb(content_generator::build_piano(*keyboard)).value());
  EXPECT_TRUE(content_generator::to_glb(content_generator::build_chair(shipped->chair)).value() ==
              content_generator::to_glb(content_generator::build_chair()).value());
  EXPECT_TRUE(content_generator::to_glb(content_generator::build_music_stand(shipped->music_stand))
                  .value() ==
              content_generator::to_glb(content_generator::build_music_stand()).value());
  std::filesystem::remove_all(dir);
}

TEST(ContentGenerator, BadDimensionsAreOneLineErrorsWithTheJsonPath) {
  const std::filesystem::path dir = unique_temp_path("bad-dimensions");
  std::filesystem::remove_all(dir);
  auto document = content::read_json_file(content_dir() / "generator" / "dimensions.json");
  ASSERT_TRUE(document.ok()) << document.error().message;
  struct Case {
    const char* name;
    std::string json;
    const char* expected;
  };
  nlohmann::json negative = *document;
  negative["chair"]["seat_top_mm"] = -5.0;
  nlohmann::json unknown = *document;
  unknown["piano"]["key_colour"] = 1.0;
  nlohmann::json missing = *document;
  missing.erase("music_stand");
  nlohmann::json inverted = *document;
  inverted["chair"]["backrest_top_mm"] = 600.0;
  nlohmann::json performer = *document;
  performer["performer"]["upper_arm_length_mm"] = 5000.0;
  nlohmann::json tuba = *document;
  tuba["tuba"]["valve_pitch_mm"] = 10.0;
  nlohmann::json horn = *document;
  horn["horn"].erase("rotor_diameter_mm");
  nlohmann::json throat = *document;
  throat["horn"]["bell_throat_diameter_mm"] = 500.0;
  const Case cases[] = {
      {"negative", negative.dump(), "dimensions.json: /chair/seat_top_mm"},
      {"unknown", unknown.dump(), "dimensions.json: /piano"},
      {"missing", missing.dump(), "dimensions.json: /music_stand: missing"},
      {"inverted", inverted.dump(), "dimensions.json: /chair/backrest_bottom_mm"},
      {"not_json", "{\"piano\": ", "dimensions.json"},
      {"performer", performer.dump(), "dimensions.json: /performer/upper_arm_length_mm"},
      {"tuba", tuba.dump(), "dimensions.json: /tuba/valve_pitch_mm"},
      {"horn", horn.dump(), "dimensions.json: /horn/rotor_diameter_mm: missing"},
      {"throat", throat.dump(), "dimensions.json: /horn/bell_throat_diameter_mm"},
  };
  for (const Case& c : cases) {
    const auto content = content_with_dimensions(dir / c.name, c.json);
    const ProcessResult run =
        run_generator("'" + (dir / "out").string() + "' --content '" + content.string() + "'", dir);
    EXPECT_EQ(run.exit_code, 2) << c.name;
    EXPECT_EQ(run.stderr_text.rfind("error: ", 0), 0u) << run.stderr_text;
    EXPECT_NE(run.stderr_text.find(c.expected), std::string::npos) << run.stderr_text;
    ASSERT_FALSE(run.stderr_text.empty()) << c.name;
    EXPECT_EQ(run.stderr_text.find('\n'), run.stderr_text.size() - 1) << run.stderr_text;
    EXPECT_FALSE(std::filesystem::exists(dir / "out" / "piano.glb")) << c.name;
    EXPECT_FALSE(std::filesystem::exists(dir / "out" / "performer.glb")) << c.name;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tutti::test
