// SPDX-License-Identifier: MIT
#include <tutti/runtime/input_bindings.hpp>

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

namespace tutti::runtime {
namespace {

TEST(InputBindingsTest, TransportKeys) {
  EXPECT_EQ(key_action(GLFW_KEY_SPACE, 0).kind, ActionKind::toggle_play);
  const Action back = key_action(GLFW_KEY_LEFT, 0);
  EXPECT_EQ(back.kind, ActionKind::seek_by);
  EXPECT_DOUBLE_EQ(back.amount, -5.0);
  const Action forward = key_action(GLFW_KEY_RIGHT, 0);
  EXPECT_EQ(forward.kind, ActionKind::seek_by);
  EXPECT_DOUBLE_EQ(forward.amount, 5.0);
  EXPECT_EQ(key_action(GLFW_KEY_HOME, 0).kind, ActionKind::seek_to_start);
  EXPECT_EQ(key_action(GLFW_KEY_ESCAPE, 0).kind, ActionKind::quit);
}

TEST(InputBindingsTest, CameraKeys) {
  EXPECT_EQ(key_action(GLFW_KEY_0, 0).kind, ActionKind::director);
  for (int n = 1; n <= 9; ++n) {
    const Action a = key_action(GLFW_KEY_0 + n, 0);
    EXPECT_EQ(a.kind, ActionKind::scene_camera) << n;
    EXPECT_EQ(a.index, n - 1);
  }
  EXPECT_EQ(key_action(GLFW_KEY_F, 0).kind, ActionKind::free_camera);
}

TEST(InputBindingsTest, LoopAndTempoKeys) {
  EXPECT_EQ(key_action(GLFW_KEY_LEFT_BRACKET, 0).kind, ActionKind::loop_start);
  EXPECT_EQ(key_action(GLFW_KEY_RIGHT_BRACKET, 0).kind, ActionKind::loop_end);
  EXPECT_EQ(key_action(GLFW_KEY_BACKSLASH, 0).kind, ActionKind::loop_clear);
  EXPECT_EQ(key_action(GLFW_KEY_MINUS, 0).kind, ActionKind::tempo_down);
  EXPECT_EQ(key_action(GLFW_KEY_EQUAL, 0).kind, ActionKind::tempo_up);
  EXPECT_EQ(key_action(GLFW_KEY_KP_SUBTRACT, 0).kind, ActionKind::tempo_down);
  EXPECT_EQ(key_action(GLFW_KEY_KP_ADD, 0).kind, ActionKind::tempo_up);
}

TEST(InputBindingsTest, UnboundKeysDoNothing) {
  for (int key : {GLFW_KEY_A, GLFW_KEY_Q, GLFW_KEY_ENTER, GLFW_KEY_F1, GLFW_KEY_UNKNOWN}) {
    EXPECT_EQ(key_action(key, 0).kind, ActionKind::none) << key;
  }
}

TEST(InputBindingsTest, MouseDragsAndWheel) {
  const Action orbit = drag_action(GLFW_MOUSE_BUTTON_LEFT, 0, 3.0f, -2.0f);
  EXPECT_EQ(orbit.kind, ActionKind::orbit);
  EXPECT_FLOAT_EQ(orbit.dx, 3.0f);
  EXPECT_FLOAT_EQ(orbit.dy, -2.0f);
  EXPECT_EQ(drag_action(GLFW_MOUSE_BUTTON_LEFT, GLFW_MOD_SHIFT, 1, 1).kind, ActionKind::pan);
  EXPECT_EQ(drag_action(GLFW_MOUSE_BUTTON_RIGHT, 0, 1, 1).kind, ActionKind::pan);
  EXPECT_EQ(drag_action(GLFW_MOUSE_BUTTON_MIDDLE, 0, 1, 1).kind, ActionKind::pan);
  EXPECT_EQ(drag_action(GLFW_MOUSE_BUTTON_4, 0, 1, 1).kind, ActionKind::none);
  const Action zoom = scroll_action(2.0);
  EXPECT_EQ(zoom.kind, ActionKind::zoom);
  EXPECT_DOUBLE_EQ(zoom.amount, 2.0);
  EXPECT_EQ(scroll_action(0.0).kind, ActionKind::none);
}

TEST(InputBindingsTest, TempoLadderStaysWithinItsEnds) {
  EXPECT_DOUBLE_EQ(step_tempo(1.0, 1), 1.1);
  EXPECT_DOUBLE_EQ(step_tempo(1.0, -1), 0.9);
  EXPECT_DOUBLE_EQ(step_tempo(0.75, -1), 0.7);
  EXPECT_DOUBLE_EQ(step_tempo(0.1, -1), 0.1);
  EXPECT_DOUBLE_EQ(step_tempo(4.0, 1), 4.0);
  EXPECT_DOUBLE_EQ(step_tempo(2.0, 1), 3.0);
  EXPECT_DOUBLE_EQ(step_tempo(0.85, 1), 0.9);  // off the ladder: the next rung
  EXPECT_DOUBLE_EQ(step_tempo(0.85, -1), 0.8);
  double tempo = kMinTempo;
  int steps = 0;
  while (tempo < kMaxTempo && steps < 100) {
    const double next = step_tempo(tempo, 1);
    EXPECT_GT(next, tempo);
    tempo = next;
    ++steps;
  }
  EXPECT_EQ(steps, 15);
}

}  // namespace
}  // namespace tutti::runtime
