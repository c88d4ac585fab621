// SPDX-License-Identifier: MIT
#pragma once
// ImGuiLayer: Dear ImGui (1.86, Debian's libimgui-dev) drawn over a WindowTarget's picture, for
// the editor's panels. It owns the ImGui context, the GLFW and Vulkan backends, their
// descriptor pool and the font texture. ImGui 1.86's Vulkan backend needs a classic
// VkRenderPass, so it draws in the target's overlay pass (WindowTarget::overlay_render_pass()).
//
//   auto imgui = ImGuiLayer::create(context, window, target);
//   every frame:
//     window.poll_events();
//     imgui->new_frame();
//     ImGui::Begin("Transport"); ... ImGui::End();
//     auto frame = target.begin_frame();
//     player.record(*frame, target);                // the 3D main pass
//     imgui->record_overlay(*frame, target);        // begin_overlay_pass, draw, end_overlay_pass
//     target.end_frame();
//
// ImGui's backends are global: one ImGuiLayer at a time, on GLFW's main thread. The context,
// the window and the target outlive the layer.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>

#include <tutti/core/result.hpp>
#include <tutti/render/vulkan_context.hpp>
#include <tutti/render/window.hpp>
#include <tutti/render/window_target.hpp>

struct ImGuiContext;

namespace tutti::runtime {

struct ImGuiLayerOptions {
  // GLFW callbacks for ImGui's input (chained to those already installed).
  bool install_callbacks = true;
  bool save_settings = false;  // false: no imgui.ini is read or written
  // ImGui's style colours are sRGB values for a UNORM target; the swap chain is sRGB (it
  // encodes on store), so they are decoded to linear light once here and look as designed.
  // Colours the caller passes to ImGui itself are still taken as linear.
  bool linearise_style = true;
};

class ImGuiLayer {
 public:
  // An error when another ImGuiLayer exists, or a backend or the font upload fails.
  static Result<std::unique_ptr<ImGuiLayer>> create(render::VulkanContext& context,
                                                    render::Window& window,
                                                    render::WindowTarget& target,
                                                    const ImGuiLayerOptions& options = {});
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // Starts an ImGui frame (follows a change of the swap chain's image count first).
  void new_frame();
  // Ends the ImGui frame and records its draw lists; inside the overlay pass.
  void render(VkCommandBuffer commands);
  // begin_overlay_pass, render, end_overlay_pass: after the main pass, before end_frame.
  void record_overlay(const render::RecordingFrame& frame, render::WindowTarget& target);

  ImGuiContext* imgui_context() const { return imgui_; }
  // True when ImGui wants the mouse or the keyboard (the viewport should not act on them).
  bool wants_mouse() const;
  bool wants_keyboard() const;

 private:
  ImGuiLayer(render::VulkanContext& context, render::WindowTarget& target)
      : context_(context), target_(target) {}
  Status upload_fonts();

  render::VulkanContext& context_;
  render::WindowTarget& target_;
  ImGuiContext* imgui_ = nullptr;
  bool glfw_backend_ = false;
  bool vulkan_backend_ = false;
  render::DeviceHandle<VkDescriptorPool> pool_;
  std::uint32_t image_count_ = 0;
  bool frame_begun_ = false;
};

}  // namespace tutti::runtime
