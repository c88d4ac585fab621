// SPDX-License-Identifier: MIT
// Any number of pianists: the "pianists" array, the older single "pianist" object, and what
// the loader refuses (both keys, a name twice, two pianos on one spot, one part for two players).
// A pianist may share a brass player's name, as before: the export keeps their clips apart.
#include <tutti/scene/load_scene.hpp>
#include <tutti/brass/brass_players.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/piano/keyboard_players.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "scene_test_support.hpp"

namespace tutti::scene {
namespace {

using nlohmann::json;
using test::scenes_dir;

json duo() {
  return json::parse(R"({
    "music": "../music/piano_duo.musicxml",
    "seed": 5,
    "pianists": [
      {"parts": ["Piano I"], "position_m": [-0.85, 0, 0.6]},
      {"parts": ["Piano II"], "position_m": [0.85, 0, 0.6], "hand_size": "large"}
    ],
    "cameras": [{"name": "wide", "position_m": [0, 1.7, 3.6], "target_m": [0, 0.95, 0.2]}]
  })");
}

std::string load_error_of(const json& document) {
  auto scene = parse_scene(document, "s.json", scenes_dir(), performance::scene_load_options());
  if (!scene.ok()) return scene.error().message;
  auto scores = load_scene_music(*scene);
  return scores.ok() ? "(loaded)" : scores.error().message;
}

TEST(Pianists, TheDuoLoadsWithTwoPianists) {
  auto scene = load_scene(scenes_dir() / "piano_duo.json", performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  ASSERT_EQ(piano::keyboard_players(*scene).size(), 2u);
  EXPECT_TRUE(brass::brass_players(*scene).empty());
  EXPECT_EQ(piano::keyboard_players(*scene)[0].name, "pianist");
  EXPECT_EQ(piano::keyboard_players(*scene)[1].name, "pianist 2");
  EXPECT_EQ(piano::keyboard_players(*scene)[0].pointer, "/pianists/0");
  EXPECT_EQ(piano::keyboard_players(*scene)[1].pointer, "/pianists/1");
  EXPECT_EQ(piano::keyboard_players(*scene)[1].hand_size, "small");
  auto scores = load_scene_music(*scene);
  ASSERT_TRUE(scores.ok()) << scores.error().message;
}

TEST(Pianists, NamesAndSeedsWhenNotGiven) {
  auto scene = parse_scene(duo(), "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(piano::keyboard_players(*scene)[0].name, "pianist");
  EXPECT_EQ(piano::keyboard_players(*scene)[1].name, "pianist 2");
  // The first pianist's seed is the one a single-pianist scene always had; the second's is
  // its own, and differs from every performer's stream.
  EXPECT_EQ(piano::keyboard_players(*scene)[0].seed, derive_seed(5, 0));
  EXPECT_EQ(piano::keyboard_players(*scene)[1].seed,
            derive_seed(5, piano::keyboard_seed_stream(1)));
  EXPECT_NE(piano::keyboard_players(*scene)[1].seed, piano::keyboard_players(*scene)[0].seed);
  for (std::uint64_t stream = 1; stream < 1000; ++stream) {
    ASSERT_NE(piano::keyboard_players(*scene)[1].seed, derive_seed(5, stream));
  }
}

TEST(Pianists, TheOlderSinglePianistStillLoads) {
  auto scene = load_scene(scenes_dir() / "piano.json", performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  ASSERT_EQ(piano::keyboard_players(*scene).size(), 1u);
  EXPECT_EQ(piano::keyboard_players(*scene)[0].name, "pianist");
  EXPECT_EQ(piano::keyboard_players(*scene)[0].pointer, "/pianist");
}

TEST(Pianists, Refused) {
  json doc = duo();
  doc["pianist"] = doc["pianists"][0];
  EXPECT_EQ(load_error_of(doc),
            "s.json: /pianists: give \"pianists\" or the older \"pianist\", not both");
  doc = duo();
  doc["pianists"] = json::array();
  EXPECT_EQ(load_error_of(doc), "s.json: /pianists: must list at least one pianist");
  doc = duo();
  doc["pianists"] = json::object();
  EXPECT_EQ(load_error_of(doc), "s.json: /pianists: expected an array");
  doc = duo();
  doc["pianists"][1] = "pianist";
  EXPECT_EQ(load_error_of(doc), "s.json: /pianists/1: expected an object");
  doc = duo();
  doc["pianists"][1]["name"] = "pianist";
  EXPECT_EQ(load_error_of(doc),
            "s.json: /pianists/1/name: duplicate pianist name \"pianist\" (also /pianists/0)");
  doc = duo();
  doc["pianists"][1]["position_m"] = {-0.2, 0, 0.7};
  EXPECT_EQ(load_error_of(doc),
            "s.json: /pianists/1/position_m: the piano stands on /pianists/0's (benches "
            "0.657647 m apart; two pianos need 1.4 m)");
  doc = duo();
  doc["pianists"][1]["parts"] = {"P1"};  // Piano I by its id
  EXPECT_EQ(load_error_of(doc),
            "s.json: /pianists/1/parts/0: part \"P1\" is already played by /pianists/0/parts/0");
  doc = duo();
  doc["pianists"][1]["parts"] = {"Piano III"};
  EXPECT_EQ(load_error_of(doc),
            "s.json: /pianists/1/parts/0: no part \"Piano III\" in piano_duo.musicxml (parts: "
            "Piano I, Piano II)");
  doc = duo();
  doc["pianists"][0]["hand_sise"] = "large";
  EXPECT_EQ(load_error_of(doc),
            "s.json: /pianists/0/hand_sise: unknown key (did you mean \"hand_size\"?)");
}

TEST(Pianists, EachPlaysAKeyboardInstrumentOfTheirOwn) {
  json doc = duo();
  doc["pianists"][1]["instrument"] = "organ";
  auto scene = parse_scene(doc, "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(piano::keyboard_players(*scene)[0].instrument, "piano");
  EXPECT_EQ(piano::keyboard_players(*scene)[1].instrument, "organ");
  EXPECT_EQ(piano::keyboard_players(*scene)[1].name, "organist")
      << "an unnamed player is named for the instrument";
  doc["pianists"][0]["instrument"] = "organ";
  scene = parse_scene(doc, "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(piano::keyboard_players(*scene)[0].name, "organist");
  EXPECT_EQ(piano::keyboard_players(*scene)[1].name, "organist 2");
  doc["pianists"][1]["instrument"] = "orgen";
  EXPECT_EQ(load_error_of(doc),
            "s.json: /pianists/1/instrument: unknown keyboard instrument \"orgen\" (did you mean "
            "\"organ\"?) (instruments.json has: celesta, clavinet, electric_piano, harpsichord, "
            "organ, piano, synth)");
}

}  // namespace
}  // namespace tutti::scene
