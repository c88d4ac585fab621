// SPDX-License-Identifier: MIT
#pragma once
// Window: one GLFW window for Vulkan (no OpenGL context), with GLFW's library lifetime counted
// (glfwInit with the first window, glfwTerminate after the last). Errors are values: without a
// display, create() says so instead of crashing.
//
//   auto window = Window::create({.width = 1280, .height = 720, .title = "tutti"});
//   VulkanContextOptions options;
//   require_presentation(**window, options);            // surface extensions, swap chain
//   auto context = VulkanContext::create(options);
//   auto target = WindowTarget::create(**context, **window);
//   while (!(*window)->should_close()) { (*window)->poll_events(); ... }
//
// GLFW is single-threaded: create, use and destroy windows on the main thread only. A Window
// holds no Vulkan object, so it may outlive or predate the VulkanContext; a WindowTarget (which
// owns the surface) must be destroyed before its Window.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <tutti/core/result.hpp>
#include <tutti/render/vulkan_context.hpp>

struct GLFWwindow;

namespace tutti::render {

struct WindowOptions {
  std::uint32_t width = 1280;  // screen coordinates (the framebuffer may be larger on HiDPI)
  std::uint32_t height = 720;
  std::string title = "tutti";
  bool resizable = true;
};

class Window {
 public:
  // An error when GLFW cannot start (no display: "cannot open a window: no display ..."), when
  // it finds no Vulkan loader, or when the window cannot be made. width, height >= 1.
  static Result<std::unique_ptr<Window>> create(const WindowOptions& options);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }

  // Size of the drawable area in pixels; 0x0 while minimised.
  struct Size {
    std::uint32_t width = 0, height = 0;
  };
  Size framebuffer_size() const;
  // Asks the window system for a new client size (screen coordinates); it arrives with a later
  // poll_events(), possibly changed by the window manager.
  void set_size(std::uint32_t width, std::uint32_t height);

  bool should_close() const;
  void request_close();
  void poll_events();
  // Blocks until an event arrives (used while minimised).
  void wait_events();

  // The Vulkan instance extensions GLFW needs for surfaces on this platform
  // (glfwGetRequiredInstanceExtensions), e.g. VK_KHR_surface, VK_KHR_xcb_surface.
  std::vector<std::string> required_instance_extensions() const;

 private:
  Window() = default;
  GLFWwindow* window_ = nullptr;
  bool glfw_initialised_ = false;  // this window holds one count of the GLFW library
};

// Adds what presenting to `window` needs to `options`: its instance extensions,
// VK_KHR_swapchain, and a graphics queue family that can present
// (glfwGetPhysicalDevicePresentationSupport).
void require_presentation(const Window& window, VulkanContextOptions& options);

}  // namespace tutti::render
