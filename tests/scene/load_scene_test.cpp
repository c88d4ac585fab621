// SPDX-License-Identifier: MIT
#include <tutti/scene/load_scene.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include <tutti/brass/brass_players.hpp>
#include <tutti/music/load_score.hpp>
#include <tutti/piano/keyboard_players.hpp>
#include <tutti/scene/asset_mapping.hpp>
#include <tutti/performance/families.hpp>
#include "scene_test_support.hpp"

namespace tutti::scene {
namespace {

using nlohmann::json;
using test::error_of;
using test::scenes_dir;
using test::ScratchDir;

// ---- the shipped scenes -------------------------------------------------------------------

TEST(ShippedScenes, QuartetLoads) {
  auto scene = load_scene(scenes_dir() / "quartet.json", performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->source, "quartet.json");
  ASSERT_EQ(scene->music.size(), 1u);
  EXPECT_EQ(scene->music[0].filename(), "quartet.musicxml");
  EXPECT_TRUE(std::filesystem::is_regular_file(scene->music[0]));
  ASSERT_EQ(brass::brass_players(*scene).size(), 4u);
  EXPECT_TRUE(piano::keyboard_players(*scene).empty());
  const char* instruments[] = {"trumpet_bb", "trumpet_bb", "trombone_tenor", "trombone_tenor"};
  int leads = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const brass::BrassPlayer& p = brass::brass_players(*scene)[i];
    EXPECT_EQ(p.instrument, instruments[i]) << p.name;
    EXPECT_EQ(p.voice, 1);
    EXPECT_EQ(p.position_m.y, 0.0);
    EXPECT_GT(p.position_m.z, -1.0) << "players stand near the front, facing +Z";
    EXPECT_LE(std::abs(p.facing_deg), 30.0) << "facing the audience";
    leads += p.lead ? 1 : 0;
  }
  EXPECT_EQ(leads, 1);
  EXPECT_TRUE(brass::brass_players(*scene)[0].lead);
  EXPECT_DOUBLE_EQ(*brass::brass_players(*scene)[0].variation.sway_amount, 0.6);
  EXPECT_FALSE(brass::brass_players(*scene)[0].variation.sway_phase.has_value());
  // Seeds: Trombone 1 gives its own; the others derive from the scene seed (7).
  EXPECT_TRUE(brass::brass_players(*scene)[2].seed_given);
  EXPECT_EQ(brass::brass_players(*scene)[2].seed, 11u);
  EXPECT_FALSE(brass::brass_players(*scene)[0].seed_given);
  EXPECT_EQ(brass::brass_players(*scene)[0].seed, derive_seed(7, 1));
  EXPECT_EQ(brass::brass_players(*scene)[3].seed, derive_seed(7, 4));
  // Several cuts over the piece.
  EXPECT_GE(scene->cameras.size(), 4u);
  EXPECT_GE(scene->shots.size(), 6u);
  EXPECT_EQ(scene->camera_at(0.0).name, "wide");
  EXPECT_EQ(scene->camera_at(5.0).name, "lead_trumpet");
  EXPECT_EQ(scene->camera_at(12.0).name, "trombones");
  EXPECT_EQ(scene->camera_at(21.0).name, "high");
  EXPECT_EQ(scene->camera_at(39.0).name, "wide");
  EXPECT_EQ(scene->output.width, 1920);
  EXPECT_FALSE(scene->output.end_s.has_value());
  // Light directions are normalised.
  const Vec3 d = scene->lights.key.direction;
  EXPECT_NEAR(d.x * d.x + d.y * d.y + d.z * d.z, 1.0, 1e-12);
}

TEST(ShippedScenes, PianoLoads) {
  auto scene = load_scene(scenes_dir() / "piano.json", performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_TRUE(brass::brass_players(*scene).empty());
  ASSERT_EQ(piano::keyboard_players(*scene).size(), 1u);
  EXPECT_EQ(piano::keyboard_players(*scene).front().parts, std::vector<std::string>{"Piano"});
  EXPECT_EQ(piano::keyboard_players(*scene).front().hand_size, "medium");
  EXPECT_GT(piano::keyboard_players(*scene).front().position_m.z, 0.0) << "the pianist sits at +Z";
  EXPECT_DOUBLE_EQ(piano::keyboard_players(*scene).front().facing_deg, 180.0);
  EXPECT_EQ(piano::keyboard_players(*scene).front().seed, derive_seed(3, 0));
  EXPECT_GE(scene->cameras.size(), 2u);
  EXPECT_GE(scene->shots.size(), 3u);
  EXPECT_EQ(scene->camera_at(0.0).name, "wide");
  EXPECT_EQ(scene->camera_at(6.0).name, "hands");
}

TEST(ShippedScenes, MusicLoadsAndHasEveryPart) {
  for (const char* name : {"quartet.json", "piano.json"}) {
    auto scene = load_scene(scenes_dir() / name, performance::scene_load_options());
    ASSERT_TRUE(scene.ok()) << scene.error().message;
    auto scores = load_scene_music(*scene);
    ASSERT_TRUE(scores.ok()) << scores.error().message;
    ASSERT_EQ(scores->size(), scene->music.size());
    for (const brass::BrassPlayer& p : brass::brass_players(*scene)) {
      EXPECT_GE(find_part((*scores)[p.music_file], p.part), 0) << name << ": " << p.part;
    }
    if (!piano::keyboard_players(*scene).empty()) {
      for (const std::string& part : piano::keyboard_players(*scene).front().parts) {
        EXPECT_GE(find_part((*scores)[piano::keyboard_players(*scene).front().music_file], part), 0)
            << name << ": " << part;
      }
    }
    // Every cut happens while the music plays.
    EXPECT_LT(scene->shots.back().start_s, (*scores)[0].duration_s()) << name;
  }
}

TEST(ShippedScenes, QuartetMusicIsPlayableBrass) {
  auto score = music::load_score(test::source_dir() / "content/music/quartet.musicxml");
  ASSERT_TRUE(score.ok()) << score.error().message;
  EXPECT_GE(score->duration_s(), 30.0);
  EXPECT_LE(score->duration_s(), 60.0);
  ASSERT_EQ(score->parts.size(), 4u);
  // Written ranges: trumpets C4..G5 written (B♭: sounding two semitones lower), trombones E2..F4.
  const int lowest[] = {60 - 2, 60 - 2, 40, 40};
  const int highest[] = {79 - 2, 79 - 2, 65, 65};
  for (int part = 0; part < 4; ++part) {
    EXPECT_EQ(score->parts[part].transpose_semitones, part < 2 ? -2 : 0);
    double previous_end = 0.0;
    double longest_gap = 0.0;
    int notes = 0;
    for (const music::Note& n : score->notes) {
      if (n.part != part) continue;
      ++notes;
      EXPECT_GE(n.pitch, lowest[part]) << score->parts[part].name;
      EXPECT_LE(n.pitch, highest[part]) << score->parts[part].name;
      longest_gap = std::max(longest_gap, n.onset_s - previous_end);
      previous_end = n.offset_s;
    }
    EXPECT_EQ(notes, 32);
    EXPECT_GT(longest_gap, 1.0) << score->parts[part].name << " has a rest to breathe in";
  }
}

// ---- errors -------------------------------------------------------------------------------

// A small valid scene; each error test breaks one thing. Relative paths resolve against
// content/scenes/ so the music is the real quartet.
json valid_scene() {
  return json::parse(R"({
    "music": "../music/quartet.musicxml",
    "seed": 1,
    "performers": [
      {"name": "T1", "instrument": "trumpet_bb", "part": "Trumpet 1", "position_m": [-1, 0, 0],
       "variation": {"sway_amount": 0.5}},
      {"name": "B1", "instrument": "trombone_tenor", "part": "Trombone 1", "position_m": [1, 0, 0]}
    ],
    "cameras": [{"name": "wide", "position_m": [0, 1.6, 6], "target_m": [0, 1.1, 0]},
                {"name": "close", "position_m": [-1, 1.5, 2], "target_m": [-1, 1.4, 0]}],
    "shots": [{"camera": "wide", "start_s": 0}, {"camera": "close", "start_s": 8.5},
              {"camera": "wide", "start_s": 12}]
  })");
}

TEST(SceneErrors, TheValidBaseLoads) {
  auto scene = parse_scene(valid_scene(), "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(brass::brass_players(*scene).size(), 2u);
  EXPECT_EQ(scene->shots.size(), 3u);
  EXPECT_EQ(scene->output.width, 1280);  // defaults
  EXPECT_FALSE(scene->output.soft_shadows);
  EXPECT_EQ(scene->lights.fill.intensity, 0.6);
  json soft = valid_scene();
  soft["output"] = {{"shadows", "soft"}};
  auto with_soft = parse_scene(soft, "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(with_soft.ok()) << with_soft.error().message;
  EXPECT_TRUE(with_soft->output.soft_shadows);
}

TEST(SceneErrors, UnknownKeyAtTopLevel) {
  json doc = valid_scene();
  doc["camera"] = json::array();
  EXPECT_EQ(error_of(doc), "s.json: /camera: unknown key (did you mean \"cameras\"?)");
}

TEST(SceneErrors, UnknownKeyNested) {
  json doc = valid_scene();
  doc["performers"][1]["positon_m"] = {0, 0, 0};
  EXPECT_EQ(error_of(doc),
            "s.json: /performers/1/positon_m: unknown key (did you mean \"position_m\"?)");
  doc = valid_scene();
  doc["output"] = {{"widht", 640}};
  EXPECT_EQ(error_of(doc), "s.json: /output/widht: unknown key (did you mean \"width\"?)");
  doc = valid_scene();
  doc["lights"] = {{"key", {{"colour", {1, 1, 1}}}}};
  EXPECT_EQ(error_of(doc), "s.json: /lights/key/colour: unknown key (did you mean \"color\"?)");
  doc = valid_scene();
  doc["cameras"][0]["fov"] = 30;
  EXPECT_EQ(error_of(doc), "s.json: /cameras/0/fov: unknown key (did you mean \"fov_deg\"?)");
}

TEST(SceneErrors, WrongType) {
  json doc = valid_scene();
  doc["performers"][0]["name"] = 5;
  EXPECT_EQ(error_of(doc), "s.json: /performers/0/name: expected a string");
  doc = valid_scene();
  doc["cameras"][1]["fov_deg"] = "wide";
  EXPECT_EQ(error_of(doc), "s.json: /cameras/1/fov_deg: expected a number");
  doc = valid_scene();
  doc["performers"][0]["position_m"] = {1, 2};
  EXPECT_EQ(error_of(doc), "s.json: /performers/0/position_m: expected [x, y, z]");
  doc = valid_scene();
  doc["performers"][0]["position_m"] = {1, "up", 0};
  EXPECT_EQ(error_of(doc), "s.json: /performers/0/position_m/1: expected a number");
  doc = valid_scene();
  doc["performers"][0]["lead"] = 1;
  EXPECT_EQ(error_of(doc), "s.json: /performers/0/lead: expected true or false");
  doc = valid_scene();
  doc["performers"][0]["voice"] = 1.5;
  EXPECT_EQ(error_of(doc), "s.json: /performers/0/voice: expected an integer");
  doc = valid_scene();
  doc["seed"] = -4;
  EXPECT_EQ(error_of(doc),
            "s.json: /seed: expected a non-negative integer (at most 18446744073709551615)");
  doc = valid_scene();
  doc["performers"] = json::object();
  EXPECT_EQ(error_of(doc), "s.json: /performers: expected an array");
  doc = valid_scene();
  doc["music"] = 3;
  EXPECT_EQ(error_of(doc), "s.json: /music: expected a file path or an array of them");
}

TEST(SceneErrors, OutOfRange) {
  json doc = valid_scene();
  doc["performers"][0]["variation"]["sway_amount"] = 1.5;
  EXPECT_EQ(error_of(doc), "s.json: /performers/0/variation/sway_amount: must be in [0, 1]");
  doc = valid_scene();
  doc["cameras"][0]["fov_deg"] = 200;
  EXPECT_EQ(error_of(doc), "s.json: /cameras/0/fov_deg: must be in [5, 120]");
  doc = valid_scene();
  doc["performers"][1]["facing_deg"] = 400;
  EXPECT_EQ(error_of(doc), "s.json: /performers/1/facing_deg: must be in [-360, 360]");
  doc = valid_scene();
  doc["performers"][1]["voice"] = 0;
  EXPECT_EQ(error_of(doc), "s.json: /performers/1/voice: must be in [1, 16]");
  doc = valid_scene();
  doc["output"] = {{"msaa", 3}};
  EXPECT_EQ(error_of(doc), "s.json: /output/msaa: must be 1, 2, 4 or 8");
  doc = valid_scene();
  doc["output"] = {{"shadows", "blurry"}};
  EXPECT_EQ(error_of(doc), "s.json: /output/shadows: must be \"hard\" or \"soft\"");
  doc = valid_scene();
  doc["output"] = {{"width", 641}};
  EXPECT_EQ(error_of(doc), "s.json: /output/width: must be even (for video encoders)");
  doc = valid_scene();
  doc["output"] = {{"background", {0, 0, 2}}};
  EXPECT_EQ(error_of(doc), "s.json: /output/background/2: must be in [0, 1]");
  doc = valid_scene();
  doc["output"] = {{"start_s", 5}, {"end_s", 5}};
  EXPECT_EQ(error_of(doc), "s.json: /output/end_s: must be later than start_s (5 s)");
  doc = valid_scene();
  doc["performers"][0]["music_file"] = 1;
  EXPECT_EQ(error_of(doc), "s.json: /performers/0/music_file: must be in [0, 0]");
  doc = valid_scene();
  doc["lights"] = {{"fill", {{"direction", {0, 0, 0}}}}};
  EXPECT_EQ(error_of(doc), "s.json: /lights/fill/direction: must not be zero");
  doc = valid_scene();
  doc["performers"][0]["stance"] = "kneeling";
  EXPECT_EQ(error_of(doc), "s.json: /performers/0/stance: must be \"standing\" or \"seated\"");
}

TEST(SceneErrors, MissingMusicFile) {
  json doc = valid_scene();
  doc["music"] = "../music/nope.musicxml";
  EXPECT_EQ(error_of(doc), "s.json: /music: no such file \"../music/nope.musicxml\"");
  doc["music"] = {"../music/quartet.musicxml", "missing.mid"};
  EXPECT_EQ(error_of(doc), "s.json: /music/1: no such file \"missing.mid\"");
  doc["music"] = json::array();
  EXPECT_EQ(error_of(doc), "s.json: /music: must name at least one file");
  doc.erase("music");
  EXPECT_EQ(error_of(doc), "s.json: /music: missing");
}

TEST(SceneErrors, UnknownCameraInAShot) {
  json doc = valid_scene();
  doc["shots"][1]["camera"] = "closeup";
  EXPECT_EQ(error_of(doc),
            "s.json: /shots/1/camera: no camera named \"closeup\" (cameras: wide, close)");
}

TEST(SceneErrors, ShotsOutOfOrder) {
  json doc = valid_scene();
  doc["shots"][2]["start_s"] = 8.5;
  EXPECT_EQ(error_of(doc),
            "s.json: /shots/2/start_s: must be later than the previous shot's start (8.5 s)");
  doc = valid_scene();
  doc["shots"][0]["start_s"] = 1;
  EXPECT_EQ(error_of(doc), "s.json: /shots/0/start_s: the first shot must start at 0");
  doc = valid_scene();
  doc["shots"] = json::array();
  EXPECT_EQ(error_of(doc), "s.json: /shots: must list at least one shot (or be left out)");
}

TEST(SceneErrors, NoShotListMeansTheFirstCamera) {
  json doc = valid_scene();
  doc.erase("shots");
  auto scene = parse_scene(doc, "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  ASSERT_EQ(scene->shots.size(), 1u);
  EXPECT_EQ(scene->camera_at(100.0).name, "wide");
}

TEST(SceneErrors, CamerasAndPeople) {
  json doc = valid_scene();
  doc["cameras"] = json::array();
  EXPECT_EQ(error_of(doc), "s.json: /cameras: a scene needs at least one camera");
  doc = valid_scene();
  doc["cameras"][1]["name"] = "wide";
  EXPECT_EQ(error_of(doc),
            "s.json: /cameras/1/name: duplicate camera name \"wide\" (also /cameras/0)");
  doc = valid_scene();
  doc["cameras"][0]["target_m"] = {0, 1.6, 6};
  EXPECT_EQ(error_of(doc), "s.json: /cameras/0/target_m: must differ from position_m");
  doc = valid_scene();
  doc["performers"] = json::array();
  EXPECT_EQ(error_of(doc),
            "s.json: /: a scene needs at least one player (performers, pianists, pianist)");
  doc = valid_scene();
  doc["performers"][1]["name"] = "T1";
  EXPECT_EQ(error_of(doc),
            "s.json: /performers/1/name: duplicate performer name \"T1\" (also /performers/0)");
  doc = valid_scene();
  doc["performers"][0]["lead"] = true;
  doc["performers"][1]["lead"] = true;
  EXPECT_EQ(error_of(doc),
            "s.json: /performers/1/lead: only one performer may lead (also /performers/0)");
  doc = valid_scene();
  doc["performers"][0].erase("position_m");
  EXPECT_EQ(error_of(doc), "s.json: /performers/0/position_m: missing");
}

TEST(SceneErrors, UnknownInstrument) {
  json doc = valid_scene();
  doc["performers"][1]["instrument"] = "kazoo";
  EXPECT_EQ(error_of(doc),
            "s.json: /performers/1/instrument: unknown instrument \"kazoo\" (known: euphonium, "
            "horn_double, trombone_tenor, trumpet_bb, trumpet_c, tuba)");
}

TEST(SceneErrors, UnknownVariationKey) {
  json doc = valid_scene();
  doc["performers"][0]["variation"]["sway"] = 0.5;
  EXPECT_EQ(error_of(doc),
            "s.json: /performers/0/variation/sway: unknown key (did you mean \"sway_amount\"?) "
            "(known: sway_amount, sway_period, "
            "sway_phase, weight_shift_rate, breath_depth, cue_strength, head_motion)");
}

TEST(SceneErrors, Pianist) {
  json doc = valid_scene();
  doc["pianist"] = {{"parts", {"Trombone 2"}}, {"hand_size", "huge"}};
  EXPECT_EQ(error_of(doc),
            "s.json: /pianist/hand_size: unknown hand size \"huge\" (hands.json has: large, "
            "medium, small)");
  doc["pianist"] = {{"parts", json::array()}};
  EXPECT_EQ(error_of(doc), "s.json: /pianist/parts: must name at least one part");
  doc["pianist"] = {{"parts", {"Trombone 2"}}, {"hands", 3}};
  EXPECT_EQ(error_of(doc), "s.json: /pianist/hands: expected a string");
  doc["pianist"] = {{"parts", {"Trombone 2"}}};
  auto scene = parse_scene(doc, "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(piano::keyboard_players(*scene).front().hand_size,
            "medium");  // hands.json's default_preset
}

TEST(SceneErrors, PartMissingFromTheMusic) {
  json doc = valid_scene();
  doc["performers"][1]["part"] = "Trombone 3";
  auto scene = parse_scene(doc, "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;  // parts are checked against the music later
  auto scores = load_scene_music(*scene);
  ASSERT_FALSE(scores.ok());
  EXPECT_EQ(scores.error().message,
            "s.json: /performers/1/part: no part \"Trombone 3\" in quartet.musicxml (parts: "
            "Trumpet 1, Trumpet 2, Trombone 1, Trombone 2)");
  // Names match case-insensitively, ids exactly.
  doc["performers"][1]["part"] = "trombone 1";
  doc["performers"][0]["part"] = "P2";
  scene = parse_scene(doc, "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(scene.ok());
  EXPECT_TRUE(load_scene_music(*scene).ok());
}

TEST(SceneErrors, UserAssetMappings) {
  const std::string example = (scenes_dir() / "examples/mixamo_character.mapping.json").string();
  json doc = valid_scene();
  doc["performers"][0]["character"] = example;
  auto scene = parse_scene(doc, "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(brass::brass_players(*scene)[0].character_mapping.filename(),
            "mixamo_character.mapping.json");

  doc["performers"][0]["character"] = "examples/nope.mapping.json";
  EXPECT_EQ(error_of(doc),
            "s.json: /performers/0/character: no such file \"examples/nope.mapping.json\"");
  doc = valid_scene();
  doc["performers"][0]["instrument_model"] = "examples/mixamo_character.mapping.json";
  EXPECT_EQ(error_of(doc),
            "s.json: /performers/0/instrument_model: \"examples/mixamo_character.mapping.json\" "
            "maps a character, expected a trumpet");
  doc = valid_scene();
  doc["performers"][1]["instrument"] = "tuba";
  doc["performers"][1]["instrument_model"] = "examples/mixamo_character.mapping.json";
  EXPECT_EQ(error_of(doc),
            "s.json: /performers/1/instrument_model: user models exist for trumpets and "
            "trombones only, not B♭B♭ tuba");
}

// ---- file-level errors ----------------------------------------------------------------------

TEST(SceneFileErrors, MissingFile) {
  const auto path = scenes_dir() / "no_such_scene.json";
  auto scene = load_scene(path, performance::scene_load_options());
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error().message, path.string() + ": no such file");
}

TEST(SceneFileErrors, EmptyFile) {
  ScratchDir dir;
  auto scene = load_scene(dir.write("empty.json", ""), performance::scene_load_options());
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error().message, "empty.json: empty file");
  scene = load_scene(dir.write("blank.json", " \n\t\n"), performance::scene_load_options());
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error().message, "blank.json: empty file");
}

TEST(SceneFileErrors, TruncatedJson) {
  std::ifstream in(scenes_dir() / "quartet.json", std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ScratchDir dir;
  const std::size_t cut = text.find("\"performers\"");
  ASSERT_NE(cut, std::string::npos);
  auto scene = load_scene(dir.write("quartet.json", text.substr(0, cut + 14)), performance::scene_load_options());
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error().message,
            "quartet.json: not valid JSON (at line 5, column 17: syntax error while parsing value "
            "- unexpected end of input; expected '[', '{', or a literal)");
}

TEST(SceneFileErrors, NotAnObject) {
  ScratchDir dir;
  auto scene = load_scene(dir.write("list.json", "[1, 2, 3]\n"), performance::scene_load_options());
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.error().message, "list.json: /: expected an object");
}

TEST(SceneFileErrors, RelativePathsResolveAgainstTheSceneFile) {
  ScratchDir dir;
  std::filesystem::copy_file(test::source_dir() / "content/music/quartet.musicxml",
                             dir.path() / "piece.musicxml");
  json doc = valid_scene();
  doc["music"] = "piece.musicxml";
  auto scene = load_scene(dir.write("here.json", doc.dump()), performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(scene->music[0], dir.path() / "piece.musicxml");
  EXPECT_EQ(scene->source, "here.json");
}

}  // namespace
}  // namespace tutti::scene
