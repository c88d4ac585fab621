// SPDX-License-Identifier: MIT
// Hold files (content/instruments/holds/): the bundled ones read, and a broken one is refused
// with one line naming the file and the JSON path.
#include <tutti/brass/hold.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "scratch_dir.hpp"

namespace tutti::brass {
namespace {

const std::filesystem::path kHolds =
    std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "instruments" / "holds";

TEST(Hold, TheTrumpetsRightFingertipsRestOnTheButtons) {
  auto hold = load_hold(kHolds / "trumpet.json");
  ASSERT_TRUE(hold) << hold.error().message;
  EXPECT_TRUE(hold->fingertips_place(1));
  EXPECT_FALSE(hold->fingertips_place(0));
  EXPECT_EQ(hold->hands[0].palm_at, "grip_left");
  EXPECT_EQ(hold->hands[1].fingertip_on[1], "valve_1");
  EXPECT_EQ(hold->hands[1].fingertip_on[2], "valve_2");
  EXPECT_EQ(hold->hands[1].fingertip_on[3], "valve_3");
  EXPECT_LT(hold->bell_tilt_standing_rad, 0.0f);  // bell a little down
  EXPECT_LT(hold->bell_tilt_seated_rad, hold->bell_tilt_standing_rad);
}

TEST(Hold, TheTromboneIsHeldByItsGrips) {
  auto hold = load_hold(kHolds / "trombone.json");
  ASSERT_TRUE(hold) << hold.error().message;
  EXPECT_EQ(hold->hands[0].palm_at, "grip_left");
  EXPECT_EQ(hold->hands[1].palm_at, "grip_right");
  // The music stand beside the slide, to the player's left; the trumpet's straight ahead.
  EXPECT_GT(hold->stand_left_m, 0.2f);
  auto trumpet = load_hold(kHolds / "trumpet.json");
  ASSERT_TRUE(trumpet) << trumpet.error().message;
  EXPECT_EQ(trumpet->stand_left_m, 0.0f);
  EXPECT_EQ(trumpet->stand_forward_m, 0.75f);
}

// The horn's right hand goes into the bell with its thumb turned in; the trombone's left elbow has
// its own pole (tucked in and forward), the right follows the hold's.
TEST(Hold, HandsCarryTheirOwnThumbAndElbow) {
  auto horn = load_hold(kHolds / "horn.json");
  ASSERT_TRUE(horn) << horn.error().message;
  EXPECT_GT(horn->hands[1].thumb_adduct_rad, 0.5f);
  EXPECT_EQ(horn->hands[0].thumb_adduct_rad, 0.0f);
  auto trombone = load_hold(kHolds / "trombone.json");
  ASSERT_TRUE(trombone) << trombone.error().message;
  ASSERT_TRUE(trombone->hands[0].elbow_pole.has_value());
  EXPECT_LT(trombone->hands[0].elbow_pole->y, 0.0f);  // in, not out
  EXPECT_FALSE(trombone->hands[1].elbow_pole.has_value());
}

TEST(Hold, BrokenFilesAreRefusedWithTheFileAndThePath) {
  test::ScratchDir dir;
  const std::string carriage =
      R"("carriage": {"standing": {"bell_tilt_deg": -9}, "seated": {"bell_tilt_deg": -12}},
         "elbows": {"down": 1, "out": 0.8, "back": 0.3},)";
  const std::string left = R"("left_hand": {"palm_at": "grip_left", "finger_curl_deg": [55, 45, 30]})";
  const struct {
    const char* name;
    std::string text;
    const char* expected;
  } cases[] = {
      {"truncated.json", "{\"carriage\": {", "truncated.json"},
      {"unknown_key.json", "{" + carriage + left + R"(, "right_hand": {"palm_at": "grip_right",
          "finger_curl_deg": [1, 2, 3], "wrist": 4}})",
       "/right_hand"},
      {"no_right.json", "{" + carriage + left + "}", "/right_hand: missing"},
      {"bad_curl.json", "{" + carriage + left + R"(, "right_hand": {"palm_at": "grip_right",
          "finger_curl_deg": [1, 2]}})",
       "/right_hand/finger_curl_deg"},
      {"huge_curl.json", "{" + carriage + left + R"(, "right_hand": {"palm_at": "grip_right",
          "finger_curl_deg": [1, 2, 900]}})",
       "/right_hand/finger_curl_deg/2"},
      {"neither.json", "{" + carriage + left + R"(, "right_hand": {"finger_curl_deg": [1, 2, 3]}})",
       "either palm_at or fingertips_on"},
      {"adduct.json", "{" + carriage + left + R"(, "right_hand": {"palm_at": "grip_right",
          "finger_curl_deg": [1, 2, 3], "thumb_adduct_deg": 95}})",
       "/right_hand/thumb_adduct_deg: must be in -60..60"},
      {"elbow.json", "{" + carriage + left + R"(, "right_hand": {"palm_at": "grip_right",
          "finger_curl_deg": [1, 2, 3], "elbow": {"down": "low"}}})",
       "/right_hand/elbow"},
      {"stand.json", "{" + carriage + left + R"(, "right_hand": {"palm_at": "grip_right",
          "finger_curl_deg": [1, 2, 3]}, "music_stand": {"forward_m": 0.1}})",
       "/music_stand/forward_m"},
      {"tilt.json", R"({"carriage": {"standing": {"bell_tilt_deg": "down"}, "seated": {}},
          "elbows": {"down": 1, "out": 0.8, "back": 0.3},)" + left +
                        R"(, "right_hand": {"palm_at": "grip_right", "finger_curl_deg": [1, 2, 3]}})",
       "/carriage/standing"},
  };
  for (const auto& c : cases) {
    auto hold = load_hold(dir.write(c.name, c.text));
    ASSERT_FALSE(hold) << c.name;
    const std::string& message = hold.error().message;
    EXPECT_NE(message.find(c.name), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.name << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_FALSE(load_hold(dir.path() / "missing.json"));
}

}  // namespace
}  // namespace tutti::brass
