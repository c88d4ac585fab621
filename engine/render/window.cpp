// SPDX-License-Identifier: MIT
#include <tutti/render/window.hpp>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <string>

namespace tutti::render {
namespace {

// GLFW reports errors through a callback; keep the last one for the Error we return.
std::string& last_glfw_error() {
  static std::string message;
  return message;
}

void on_glfw_error(int code, const char* description) {
  last_glfw_error() = "GLFW error " + std::to_string(code) + ": " +
                      (description != nullptr ? description : "(no description)");
}

// Windows alive; GLFW is initialised while this is > 0 (main thread only, as GLFW requires).
int& glfw_users() {
  static int users = 0;
  return users;
}

Status acquire_glfw() {
  if (glfw_users() == 0) {
    glfwSetErrorCallback(on_glfw_error);
    last_glfw_error().clear();
    if (glfwInit() != GLFW_TRUE) {
      return Error{
          "cannot open a window: no display (set DISPLAY, or use tutti render for headless "
          "output); " +
              last_glfw_error(),
          ErrorCode::environment};
    }
  }
  ++glfw_users();
  return Status::success();
}

void release_glfw() {
  if (--glfw_users() == 0) glfwTerminate();
}

}  // namespace

Result<std::unique_ptr<Window>> Window::create(const WindowOptions& options) {
  if (options.width == 0 || options.height == 0) {
    return Error{"window: size " + std::to_string(options.width) + "x" +
                 std::to_string(options.height) + " must be at least 1x1"};
  }
  if (Status s = acquire_glfw(); !s) return s.error();
  std::unique_ptr<Window> window(new Window());
  window->glfw_initialised_ = true;  // released by ~Window from here on
  if (glfwVulkanSupported() != GLFW_TRUE) {
    return Error{"cannot open a Vulkan window: GLFW found no Vulkan loader; " + last_glfw_error(),
                 ErrorCode::environment};
  }
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);  // Vulkan draws; no OpenGL context
  glfwWindowHint(GLFW_RESIZABLE, options.resizable ? GLFW_TRUE : GLFW_FALSE);
  last_glfw_error().clear();
  window->window_ =
      glfwCreateWindow(static_cast<int>(options.width), static_cast<int>(options.height),
                       options.title.c_str(), nullptr, nullptr);
  if (window->window_ == nullptr) {
    return Error{"cannot open a window: " + last_glfw_error(), ErrorCode::environment};
  }
  return window;
}

Window::~Window() {
  if (window_ != nullptr) glfwDestroyWindow(window_);
  if (glfw_initialised_) release_glfw();
}

Window::Size Window::framebuffer_size() const {
  int width = 0;
  int height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return {static_cast<std::uint32_t>(width > 0 ? width : 0),
          static_cast<std::uint32_t>(height > 0 ? height : 0)};
}

void Window::set_size(std::uint32_t width, std::uint32_t height) {
  glfwSetWindowSize(window_, static_cast<int>(width), static_cast<int>(height));
}

bool Window::should_close() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }

void Window::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void Window::poll_events() { glfwPollEvents(); }

void Window::wait_events() { glfwWaitEvents(); }

std::vector<std::string> Window::required_instance_extensions() const {
  std::uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  std::vector<std::string> out;
  for (std::uint32_t i = 0; names != nullptr && i < count; ++i) out.emplace_back(names[i]);
  return out;
}

void require_presentation(const Window& window, VulkanContextOptions& options) {
  for (std::string& name : window.required_instance_extensions()) {
    options.instance_extensions.push_back(std::move(name));
  }
  options.swapchain = true;
  options.can_present = [](VkInstance instance, VkPhysicalDevice device, std::uint32_t family) {
    return glfwGetPhysicalDevicePresentationSupport(instance, device, family) == GLFW_TRUE;
  };
}

}  // namespace tutti::render
