// SPDX-License-Identifier: MIT
#pragma once
// Reads back what the X server shows in a GLFW window (XGetImage), so a test can check that
// presented frames arrived on screen. In its own file: Xlib's macros (Status, None, Bool) must
// not meet tutti's names.

#include <cstdint>
#include <optional>

struct GLFWwindow;

namespace tutti::render::test {

struct ScreenPixel {
  int r, g, b;  // 0..255 as the X server stores it (sRGB-encoded frames arrive unchanged)
};

// The pixel at (x, y) of the window's client area; nullopt if the window is not an X11 window
// or XGetImage fails (e.g. the point is off screen).
std::optional<ScreenPixel> read_window_pixel(GLFWwindow* window, int x, int y);

}  // namespace tutti::render::test
