// SPDX-License-Identifier: MIT
// The computer keyboard as a piano: the layout, octave keys, releases after an octave change.
#include <tutti/live/keyboard_piano.hpp>

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

namespace tutti::live {
namespace {

TEST(KeyboardPiano, TwoRowsAreWhiteAndBlackKeys) {
  KeyboardPiano piano;
  EXPECT_EQ(piano.key_of(GLFW_KEY_A), 60);  // C4
  EXPECT_EQ(piano.key_of(GLFW_KEY_W), 61);
  EXPECT_EQ(piano.key_of(GLFW_KEY_S), 62);
  EXPECT_EQ(piano.key_of(GLFW_KEY_E), 63);
  EXPECT_EQ(piano.key_of(GLFW_KEY_D), 64);
  EXPECT_EQ(piano.key_of(GLFW_KEY_F), 65);
  EXPECT_EQ(piano.key_of(GLFW_KEY_T), 66);
  EXPECT_EQ(piano.key_of(GLFW_KEY_J), 71);
  EXPECT_EQ(piano.key_of(GLFW_KEY_K), 72);
  EXPECT_EQ(piano.key_of(GLFW_KEY_SEMICOLON), 76);
  EXPECT_EQ(piano.key_of(GLFW_KEY_APOSTROPHE), 77);
  // Not piano keys: the transport's and the cameras' stay theirs.
  for (int code : {GLFW_KEY_SPACE, GLFW_KEY_LEFT, GLFW_KEY_1, GLFW_KEY_MINUS, GLFW_KEY_EQUAL,
                   GLFW_KEY_LEFT_BRACKET, GLFW_KEY_ESCAPE, GLFW_KEY_R, GLFW_KEY_Q}) {
    EXPECT_FALSE(piano.key_of(code)) << code;
    EXPECT_FALSE(piano.press(code, 0.0)) << code;
  }
}

TEST(KeyboardPiano, OctaveKeysShiftWithinLimits) {
  KeyboardPiano piano;
  EXPECT_TRUE(piano.press(GLFW_KEY_X, 0.0));
  EXPECT_EQ(piano.key_of(GLFW_KEY_A), 72);
  for (int i = 0; i < 5; ++i) piano.press(GLFW_KEY_X, 0.0);
  EXPECT_EQ(piano.octave_shift(), 2);
  for (int i = 0; i < 9; ++i) piano.press(GLFW_KEY_Z, 0.0);
  EXPECT_EQ(piano.octave_shift(), -1);
  EXPECT_EQ(piano.key_of(GLFW_KEY_A), 48);
  std::vector<LiveNoteEvent> out;
  piano.poll(1.0, out);
  EXPECT_TRUE(out.empty());  // octave keys play nothing
}

TEST(KeyboardPiano, ReleaseEndsTheNoteItStarted) {
  KeyboardPiano piano;
  std::vector<LiveNoteEvent> out;
  EXPECT_TRUE(piano.press(GLFW_KEY_G, 0.10));  // G4
  EXPECT_TRUE(piano.press(GLFW_KEY_G, 0.12));  // a repeat: still one note
  piano.press(GLFW_KEY_X, 0.15);               // octave up while G is down
  EXPECT_TRUE(piano.release(GLFW_KEY_G, 0.20));
  piano.poll(0.15, out);
  ASSERT_EQ(out.size(), 1u);  // the release is later than now: not yet
  EXPECT_EQ(out[0].key, 67);
  EXPECT_TRUE(out[0].on);
  EXPECT_EQ(out[0].time_s, 0.10);
  piano.poll(0.25, out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[1].key, 67);  // not 79
  EXPECT_FALSE(out[1].on);
  EXPECT_FALSE(piano.release(GLFW_KEY_R, 0.3));
}

}  // namespace
}  // namespace tutti::live
