// SPDX-License-Identifier: MIT
#include <tutti/piano_model/keyboard.hpp>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <tutti/music/pitch.hpp>
#include <tutti/piano_model/content_dir.hpp>

namespace tutti::piano_model {
namespace {

Keyboard load_keyboard() {
  auto keyboard = Keyboard::load(default_content_dir() / "piano" / "keyboard.json");
  EXPECT_TRUE(keyboard.ok()) << (keyboard.ok() ? "" : keyboard.error().message);
  return keyboard.ok() ? *keyboard : Keyboard{};
}

TEST(Keyboard, Has88KeysFromA0ToC8) {
  const Keyboard keyboard = load_keyboard();
  EXPECT_EQ(keyboard.key_count(), 88);
  EXPECT_EQ(keyboard.lowest_key(), 21);
  EXPECT_EQ(keyboard.highest_key(), 108);
  EXPECT_FALSE(keyboard.contains(20));
  EXPECT_FALSE(keyboard.contains(109));
  EXPECT_TRUE(keyboard.contains(60));
  EXPECT_DOUBLE_EQ(keyboard.white_key_width_mm(), 23.5);
  EXPECT_DOUBLE_EQ(keyboard.x_mm(21), 11.75);  // centre of the first white key
}

TEST(Keyboard, WhiteKeysAre23point5mmApartAndBlackKeysLieBetweenNeighbours) {
  const Keyboard keyboard = load_keyboard();
  int previous_white = -1;
  int whites = 0;
  for (int key = keyboard.lowest_key(); key <= keyboard.highest_key(); ++key) {
    if (keyboard.is_black(key)) {
      EXPECT_GT(keyboard.x_mm(key), keyboard.x_mm(key - 1)) << key;
      EXPECT_LT(keyboard.x_mm(key), keyboard.x_mm(key + 1)) << key;
      continue;
    }
    ++whites;
    if (previous_white >= 0) {
      EXPECT_NEAR(keyboard.x_mm(key) - keyboard.x_mm(previous_white), 23.5, 1e-9) << key;
    }
    previous_white = key;
  }
  EXPECT_EQ(whites, 52);
  // Octave = 7 white keys = 164.5 mm for every key.
  for (int key = keyboard.lowest_key(); key + 12 <= keyboard.highest_key(); ++key) {
    EXPECT_NEAR(keyboard.x_mm(key + 12) - keyboard.x_mm(key), 164.5, 1e-9);
  }
  // C#4 sits left of the C4/D4 boundary, A#4 right of the A4/B4 boundary (real offsets).
  EXPECT_LT(keyboard.x_mm(61), 0.5 * (keyboard.x_mm(60) + keyboard.x_mm(62)));
  EXPECT_GT(keyboard.x_mm(70), 0.5 * (keyboard.x_mm(69) + keyboard.x_mm(71)));
  EXPECT_EQ(keyboard.is_black(61), music::is_black_key(61));
}

TEST(Keyboard, ErrorsNameTheJsonPath) {
  nlohmann::json doc = {
      {"lowest_key", 21},
      {"highest_key", 108},
      {"white_key_width_mm", 23.5},
      {"black_key_centres_mm",
       {{"C#", 20.5}, {"D#", 48.0}, {"F#", 89.1}, {"G#", 116.5}, {"A#", 143.9}, {"H#", 1.0}}}};
  auto bad = Keyboard::from_json(doc, "keyboard.json");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().message, "keyboard.json: /black_key_centres_mm/H#: unknown key");
  doc["black_key_centres_mm"].erase("H#");
  doc["black_key_centres_mm"]["F#"] = 200.0;
  bad = Keyboard::from_json(doc, "keyboard.json");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("/black_key_centres_mm/F#"), std::string::npos);
  auto missing = Keyboard::load("/nonexistent/keyboard.json");
  EXPECT_FALSE(missing.ok());
}

}  // namespace
}  // namespace tutti::piano_model
