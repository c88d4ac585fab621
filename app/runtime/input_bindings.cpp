// SPDX-License-Identifier: MIT
#include <tutti/runtime/input_bindings.hpp>

#include <GLFW/glfw3.h>

#include <array>

namespace tutti::runtime {
namespace {

constexpr std::array<double, 16> kTempoLadder = {0.1, 0.25, 0.5, 0.6,  0.7, 0.75, 0.8, 0.9,
                                                 1.0, 1.1,  1.25, 1.5, 1.75, 2.0, 3.0, 4.0};

Action of(ActionKind kind) {
  Action action;
  action.kind = kind;
  return action;
}

}  // namespace

Action key_action(int key, int mods) {
  (void)mods;  // no bindings use modifiers yet; the parameter keeps the signature stable
  if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9) {
    Action action = of(ActionKind::scene_camera);
    action.index = key - GLFW_KEY_1;
    return action;
  }
  switch (key) {
    case GLFW_KEY_SPACE:
      return of(ActionKind::toggle_play);
    case GLFW_KEY_LEFT:
    case GLFW_KEY_RIGHT: {
      Action action = of(ActionKind::seek_by);
      action.amount = key == GLFW_KEY_LEFT ? -kSeekStepS : kSeekStepS;
      return action;
    }
    case GLFW_KEY_HOME:
      return of(ActionKind::seek_to_start);
    case GLFW_KEY_0:
      return of(ActionKind::director);
    case GLFW_KEY_F:
      return of(ActionKind::free_camera);
    case GLFW_KEY_LEFT_BRACKET:
      return of(ActionKind::loop_start);
    case GLFW_KEY_RIGHT_BRACKET:
      return of(ActionKind::loop_end);
    case GLFW_KEY_BACKSLASH:
      return of(ActionKind::loop_clear);
    case GLFW_KEY_MINUS:
    case GLFW_KEY_KP_SUBTRACT:
      return of(ActionKind::tempo_down);
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_KP_ADD:
      return of(ActionKind::tempo_up);
    case GLFW_KEY_ESCAPE:
      return of(ActionKind::quit);
    case GLFW_KEY_F3:
      return of(ActionKind::toggle_stats);
    default:
      return of(ActionKind::none);
  }
}

Action drag_action(int button, int mods, float dx_px, float dy_px) {
  Action action;
  const bool shift = (mods & GLFW_MOD_SHIFT) != 0;
  if (button == GLFW_MOUSE_BUTTON_LEFT) {
    action.kind = shift ? ActionKind::pan : ActionKind::orbit;
  } else if (button == GLFW_MOUSE_BUTTON_RIGHT || button == GLFW_MOUSE_BUTTON_MIDDLE) {
    action.kind = ActionKind::pan;
  } else {
    return action;
  }
  action.dx = dx_px;
  action.dy = dy_px;
  return action;
}

Action scroll_action(double steps) {
  if (steps == 0.0) return of(ActionKind::none);
  Action action = of(ActionKind::zoom);
  action.amount = steps;
  return action;
}

double step_tempo(double tempo, int direction) {
  if (direction > 0) {
    for (double step : kTempoLadder) {
      if (step > tempo + 1e-9) return step;
    }
    return kTempoLadder.back();
  }
  if (direction < 0) {
    for (auto it = kTempoLadder.rbegin(); it != kTempoLadder.rend(); ++it) {
      if (*it < tempo - 1e-9) return *it;
    }
    return kTempoLadder.front();
  }
  return tempo;
}

}  // namespace tutti::runtime
