// SPDX-License-Identifier: MIT
#include "x11_window_pixels.hpp"

#include <GLFW/glfw3.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

// GLFW's X11 native access (glfw3native.h), declared here because that header also wants
// Xrandr's headers (libxrandr-dev), which nothing else needs.
extern "C" {
GLFWAPI Display* glfwGetX11Display(void);
GLFWAPI Window glfwGetX11Window(GLFWwindow* window);
}

namespace tutti::render::test {
namespace {

// 0..255 value of the channel `mask` selects in `pixel` (TrueColor visuals).
int channel(unsigned long pixel, unsigned long mask) {
  if (mask == 0) return 0;
  int shift = 0;
  while (((mask >> shift) & 1u) == 0) ++shift;
  const unsigned long max = mask >> shift;
  return static_cast<int>(((pixel & mask) >> shift) * 255u / max);
}

// Xlib's default error handler exits the process; a failed XGetImage should only fail a check.
int ignore_x_error(Display* /*display*/, XErrorEvent* /*event*/) { return 0; }

}  // namespace

std::optional<ScreenPixel> read_window_pixel(GLFWwindow* window, int x, int y) {
  Display* display = glfwGetX11Display();
  const Window xwindow = glfwGetX11Window(window);
  if (display == nullptr || xwindow == 0) return std::nullopt;
  XSync(display, False);
  auto* previous = XSetErrorHandler(ignore_x_error);
  XImage* image = XGetImage(display, xwindow, x, y, 1, 1, AllPlanes, ZPixmap);
  XSync(display, False);
  XSetErrorHandler(previous);
  if (image == nullptr) return std::nullopt;
  const unsigned long pixel = XGetPixel(image, 0, 0);
  const ScreenPixel out{channel(pixel, image->red_mask), channel(pixel, image->green_mask),
                        channel(pixel, image->blue_mask)};
  XDestroyImage(image);
  return out;
}

}  // namespace tutti::render::test
