// SPDX-License-Identifier: MIT
#pragma once
// The keys and the mouse of `tutti play` (and the editor's viewport) as actions: a pure mapping
// from GLFW key / button codes, so it is tested without a window and a game can rebind it.
//
//   Space        play / pause          0        director (the scene's shot list)
//   Left, Right  seek −5 s / +5 s       1 .. 9   scene camera 1 .. 9
//   Home         back to the start      F        free orbit camera
//   [  ]         loop start / end here  \        clear the loop
//   -  =         practice tempo down/up (0.25 .. 2)
//   Esc          quit
//   mouse: left drag orbits, right or middle drag (or Shift + left) pans, wheel zooms; any drag
//   switches to the free camera.

namespace tutti::runtime {

enum class ActionKind {
  none,
  toggle_play,
  seek_by,  // amount: seconds (score time)
  seek_to_start,
  director,      // camera: the shot list
  scene_camera,  // index: 0-based scene camera
  free_camera,
  loop_start,  // at the current time
  loop_end,
  loop_clear,
  tempo_down,
  tempo_up,
  quit,
  orbit,  // dx, dy: pixels
  pan,    // dx, dy: pixels
  zoom,   // amount: wheel steps, + = closer
  toggle_stats,  // the on-screen statistics (frame time, 3D view scale, quality): the host's
};

struct Action {
  ActionKind kind = ActionKind::none;
  double amount = 0.0;
  int index = 0;
  float dx = 0.0f;
  float dy = 0.0f;
};

inline constexpr double kSeekStepS = 5.0;
// Practice tempo, the same range for tutti render, tutti play and the editor.
inline constexpr double kMinTempo = 0.1;
inline constexpr double kMaxTempo = 4.0;

// A key press (GLFW_KEY_*, GLFW_MOD_* bits). Unbound keys: ActionKind::none.
Action key_action(int key, int mods);
// The pointer moved by (dx, dy) pixels with `button` (GLFW_MOUSE_BUTTON_*) held.
Action drag_action(int button, int mods, float dx_px, float dy_px);
// The wheel turned (GLFW's y offset; + = away from the user = closer).
Action scroll_action(double steps);

// The next practice tempo up (direction > 0) or down from `tempo` on the ladder
// 0.25, 0.5, 0.6, 0.7, 0.75, 0.8, 0.9, 1, 1.1, 1.25, 1.5, 1.75, 2; stays at the ends.
double step_tempo(double tempo, int direction);

}  // namespace tutti::runtime
