// SPDX-License-Identifier: MIT
// The pianist's performance style and where the piano's sound comes from, in a scene file.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include <tutti/piano/keyboard_players.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/performance/families.hpp>
#include "scene_test_support.hpp"

namespace tutti::scene {
namespace {

using nlohmann::json;
using test::error_of;
using test::scenes_dir;

json piano_scene(const json& pianist_extra) {
  json document = json::parse(R"({
    "music": "../music/ode_to_joy.musicxml",
    "pianist": {"parts": ["Piano"]},
    "cameras": [{"name": "wide", "position_m": [0, 1.6, 6], "target_m": [0, 1.1, 0]}]
  })");
  document["pianist"].update(pianist_extra);
  return document;
}

TEST(PianistStyle, AbsentMeansTheWrittenSoundAndNoStyle) {
  auto scene = parse_scene(piano_scene(json::object()), "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(piano::keyboard_players(*scene).front().style, "");
  EXPECT_FALSE(piano::keyboard_players(*scene).front().sound_from_keys);
}

TEST(PianistStyle, AStyleAndTheKeysSound) {
  auto scene =
      parse_scene(piano_scene({{"style", "beginner"}, {"sound", "keys"}}), "s.json", scenes_dir(), performance::scene_load_options());
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  EXPECT_EQ(piano::keyboard_players(*scene).front().style, "beginner");
  EXPECT_TRUE(piano::keyboard_players(*scene).front().sound_from_keys);
}

TEST(PianistStyle, BadValuesAreOneLineErrors) {
  EXPECT_EQ(error_of(piano_scene({{"style", "virtuoso"}})),
            "s.json: /pianist/style: unknown performance style \"virtuoso\" (styles.json has: "
            "beginner, gentle, precise)");
  EXPECT_EQ(error_of(piano_scene({{"sound", "loud"}})),
            "s.json: /pianist/sound: expected \"score\" or \"keys\", not \"loud\"");
  EXPECT_NE(error_of(piano_scene({{"style", 3}})).find("/pianist/style"), std::string::npos);
}

}  // namespace
}  // namespace tutti::scene
