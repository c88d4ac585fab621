// SPDX-License-Identifier: MIT
#include <tutti/runtime/imgui_layer.hpp>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <tutti/render/vk_result.hpp>

namespace tutti::runtime {
namespace {

bool g_layer_exists = false;  // ImGui's backends keep global state: one layer at a time

// ImGui's backend reports VkResults through this hook; it cannot return them, so the last
// failure is kept for create() to turn into an Error.
VkResult g_last_failure = VK_SUCCESS;
void check_vk_result(VkResult result) {
  if (result < 0) g_last_failure = result;
}

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

void linearise(ImGuiStyle& style) {
  for (ImVec4& color : style.Colors) {
    color.x = srgb_to_linear(color.x);
    color.y = srgb_to_linear(color.y);
    color.z = srgb_to_linear(color.z);
  }
}

std::uint32_t overlay_image_count(const render::WindowTarget& target) {
  // The backend rotates its vertex buffers over ImageCount frames: at least the frames in
  // flight, at least 2 (its minimum).
  return std::max({2u, target.swapchain_image_count(), target.frames_in_flight()});
}

}  // namespace

Result<std::unique_ptr<ImGuiLayer>> ImGuiLayer::create(render::VulkanContext& context,
                                                       render::Window& window,
                                                       render::WindowTarget& target,
                                                       const ImGuiLayerOptions& options) {
  if (g_layer_exists) return Error{"imgui layer: only one ImGuiLayer may exist at a time"};
  std::unique_ptr<ImGuiLayer> layer(new ImGuiLayer(context, target));
  g_layer_exists = true;
  IMGUI_CHECKVERSION();
  layer->imgui_ = ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  if (!options.save_settings) io.IniFilename = nullptr;
  ImGui::StyleColorsDark();
  if (options.linearise_style) linearise(ImGui::GetStyle());

  if (!ImGui_ImplGlfw_InitForVulkan(window.handle(), options.install_callbacks)) {
    return Error{"imgui layer: ImGui_ImplGlfw_InitForVulkan failed"};
  }
  layer->glfw_backend_ = true;

  // Descriptors: the font texture, and room for the editor's own images.
  const std::array<VkDescriptorPoolSize, 1> sizes = {
      VkDescriptorPoolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 64}};
  VkDescriptorPoolCreateInfo pool_info =
      render::vk_struct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pool_info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  pool_info.maxSets = 64;
  pool_info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  if (VkResult r = vkCreateDescriptorPool(context.device(), &pool_info, nullptr, &pool);
      r != VK_SUCCESS) {
    return render::vk_error("vkCreateDescriptorPool", r);
  }
  layer->pool_ =
      render::DeviceHandle<VkDescriptorPool>(context.device(), pool, vkDestroyDescriptorPool);

  layer->image_count_ = overlay_image_count(target);
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = context.instance();
  info.PhysicalDevice = context.physical_device();
  info.Device = context.device();
  info.QueueFamily = context.graphics_queue_family();
  info.Queue = context.graphics_queue();
  info.PipelineCache = VK_NULL_HANDLE;
  info.DescriptorPool = pool;
  info.Subpass = 0;
  info.MinImageCount = layer->image_count_;
  info.ImageCount = layer->image_count_;
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;  // the overlay draws on the resolved image
  info.Allocator = nullptr;
  info.CheckVkResultFn = check_vk_result;
  g_last_failure = VK_SUCCESS;
  if (!ImGui_ImplVulkan_Init(&info, target.overlay_render_pass()) || g_last_failure != VK_SUCCESS) {
    return render::vk_error("ImGui_ImplVulkan_Init", g_last_failure);
  }
  layer->vulkan_backend_ = true;
  if (Status s = layer->upload_fonts(); !s) return s.error();
  return layer;
}

Status ImGuiLayer::upload_fonts() {
  Result<VkCommandBuffer> commands = context_.allocate_command_buffer();
  if (!commands) return commands.error();
  struct FreeOnExit {
    render::VulkanContext& context;
    VkCommandBuffer commands;
    ~FreeOnExit() { vkFreeCommandBuffers(context.device(), context.command_pool(), 1, &commands); }
  } free_on_exit{context_, *commands};
  VkCommandBufferBeginInfo begin =
      render::vk_struct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  if (VkResult r = vkBeginCommandBuffer(*commands, &begin); r != VK_SUCCESS) {
    return render::vk_error("vkBeginCommandBuffer", r);
  }
  g_last_failure = VK_SUCCESS;
  if (!ImGui_ImplVulkan_CreateFontsTexture(*commands) || g_last_failure != VK_SUCCESS) {
    return render::vk_error("ImGui_ImplVulkan_CreateFontsTexture", g_last_failure);
  }
  if (VkResult r = vkEndCommandBuffer(*commands); r != VK_SUCCESS) {
    return render::vk_error("vkEndCommandBuffer", r);
  }
  VkSubmitInfo submit = render::vk_struct<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &*commands;
  if (VkResult r = vkQueueSubmit(context_.graphics_queue(), 1, &submit, VK_NULL_HANDLE);
      r != VK_SUCCESS) {
    return render::vk_error("vkQueueSubmit", r);
  }
  if (Status s = context_.wait_idle(); !s) return s;
  ImGui_ImplVulkan_DestroyFontUploadObjects();
  return Status::success();
}

ImGuiLayer::~ImGuiLayer() {
  // Frames in flight may still read the backend's buffers and the font texture.
  (void)context_.wait_idle();
  if (frame_begun_) ImGui::EndFrame();
  if (vulkan_backend_) ImGui_ImplVulkan_Shutdown();
  if (glfw_backend_) ImGui_ImplGlfw_Shutdown();
  if (imgui_ != nullptr) ImGui::DestroyContext(imgui_);
  pool_ = {};
  g_layer_exists = false;
}

void ImGuiLayer::new_frame() {
  if (frame_begun_) return;
  const std::uint32_t count = overlay_image_count(target_);
  if (count != image_count_) {
    ImGui_ImplVulkan_SetMinImageCount(count);  // waits for the device, drops the old buffers
    image_count_ = count;
  }
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  frame_begun_ = true;
}

void ImGuiLayer::render(VkCommandBuffer commands) {
  if (!frame_begun_) new_frame();  // an empty frame rather than ImGui's assertion
  ImGui::Render();
  frame_begun_ = false;
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), commands);
}

void ImGuiLayer::record_overlay(const render::RecordingFrame& frame, render::WindowTarget& target) {
  target.begin_overlay_pass();
  render(frame.commands);
  target.end_overlay_pass();
}

bool ImGuiLayer::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace tutti::runtime
