// SPDX-License-Identifier: MIT
#include <tutti/render/window_target.hpp>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#include <tutti/render/image_barrier.hpp>
#include <tutti/render/vk_result.hpp>

namespace tutti::render {
namespace {

// Tries to acquire an image this many times when the swap chain keeps going out of date.
constexpr int kAcquireAttempts = 4;

// The largest sample count <= `wanted` that colour and depth attachments both support.
VkSampleCountFlagBits clamp_samples(VkPhysicalDevice physical_device,
                                    VkSampleCountFlagBits wanted) {
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(physical_device, &properties);
  const VkSampleCountFlags supported = properties.limits.framebufferColorSampleCounts &
                                       properties.limits.framebufferDepthSampleCounts;
  for (VkSampleCountFlagBits count :
       {VK_SAMPLE_COUNT_8_BIT, VK_SAMPLE_COUNT_4_BIT, VK_SAMPLE_COUNT_2_BIT}) {
    if (count <= wanted && (supported & count) != 0) return count;
  }
  return VK_SAMPLE_COUNT_1_BIT;
}

Result<VkSurfaceFormatKHR> choose_surface_format(VkPhysicalDevice physical_device,
                                                 VkSurfaceKHR surface) {
  std::uint32_t count = 0;
  if (VkResult r = vkGetPhysicalDeviceSurfaceFormatsKHR(physical_device, surface, &count, nullptr);
      r != VK_SUCCESS) {
    return vk_error("vkGetPhysicalDeviceSurfaceFormatsKHR", r);
  }
  std::vector<VkSurfaceFormatKHR> formats(count);
  if (VkResult r =
          vkGetPhysicalDeviceSurfaceFormatsKHR(physical_device, surface, &count, formats.data());
      r != VK_SUCCESS && r != VK_INCOMPLETE) {
    return vk_error("vkGetPhysicalDeviceSurfaceFormatsKHR", r);
  }
  // Shaders write linear light; only an sRGB swap chain encodes it for the display.
  for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB}) {
    for (const VkSurfaceFormatKHR& format : formats) {
      if (format.format == wanted && format.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) {
        return format;
      }
    }
  }
  std::string available;
  for (const VkSurfaceFormatKHR& format : formats) {
    available += (available.empty() ? "" : ", ") + std::to_string(format.format);
  }
  return Error{
      "window target: the surface offers no B8G8R8A8_SRGB or R8G8B8A8_SRGB format "
      "(VkFormat values offered: " +
      available + ")"};
}

Result<VkPresentModeKHR> choose_present_mode(VkPhysicalDevice physical_device, VkSurfaceKHR surface,
                                             VkPresentModeKHR wanted) {
  std::uint32_t count = 0;
  if (VkResult r =
          vkGetPhysicalDeviceSurfacePresentModesKHR(physical_device, surface, &count, nullptr);
      r != VK_SUCCESS) {
    return vk_error("vkGetPhysicalDeviceSurfacePresentModesKHR", r);
  }
  std::vector<VkPresentModeKHR> modes(count);
  if (VkResult r =
          vkGetPhysicalDeviceSurfacePresentModesKHR(physical_device, surface, &count, modes.data());
      r != VK_SUCCESS && r != VK_INCOMPLETE) {
    return vk_error("vkGetPhysicalDeviceSurfacePresentModesKHR", r);
  }
  if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
  return VK_PRESENT_MODE_FIFO_KHR;  // every surface supports it
}

VkCompositeAlphaFlagBitsKHR choose_composite_alpha(VkCompositeAlphaFlagsKHR supported) {
  for (VkCompositeAlphaFlagBitsKHR mode :
       {VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR, VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR,
        VK_COMPOSITE_ALPHA_PRE_MULTIPLIED_BIT_KHR, VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR}) {
    if (supported & mode) return mode;
  }
  return VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
}

bool is_bgra(VkFormat format) { return format == VK_FORMAT_B8G8R8A8_SRGB; }

}  // namespace

Result<std::unique_ptr<WindowTarget>> WindowTarget::create(VulkanContext& context, Window& window,
                                                           const WindowTargetOptions& options) {
  if (!context.swapchain_enabled()) {
    return Error{
        "window target: the VulkanContext was created without VK_KHR_swapchain (pass its "
        "options through require_presentation(window, options))"};
  }
  if (options.frames_in_flight == 0) {
    return Error{"window target: frames_in_flight must be at least 1"};
  }
  switch (options.samples) {
    case VK_SAMPLE_COUNT_1_BIT:
    case VK_SAMPLE_COUNT_2_BIT:
    case VK_SAMPLE_COUNT_4_BIT:
    case VK_SAMPLE_COUNT_8_BIT:
      break;
    default:
      return Error{"window target: " + std::to_string(static_cast<int>(options.samples)) +
                   " samples; MSAA takes 1, 2, 4 or 8"};
  }
  const VkPhysicalDevice physical = context.physical_device();
  const VkDevice device = context.device();
  std::unique_ptr<WindowTarget> target(new WindowTarget(context, window));

  if (VkResult r =
          glfwCreateWindowSurface(context.instance(), window.handle(), nullptr, &target->surface_);
      r != VK_SUCCESS) {
    return vk_error("glfwCreateWindowSurface", r);
  }
  VkBool32 supported = VK_FALSE;
  if (VkResult r = vkGetPhysicalDeviceSurfaceSupportKHR(physical, context.graphics_queue_family(),
                                                        target->surface_, &supported);
      r != VK_SUCCESS) {
    return vk_error("vkGetPhysicalDeviceSurfaceSupportKHR", r);
  }
  if (supported != VK_TRUE) {
    return Error{"window target: the graphics queue of " + context.device_info().name +
                 " cannot present to this window"};
  }
  Result<VkSurfaceFormatKHR> format = choose_surface_format(physical, target->surface_);
  if (!format) return format.error();
  target->color_format_ = format->format;
  target->color_space_ = format->colorSpace;
  Result<VkPresentModeKHR> mode =
      choose_present_mode(physical, target->surface_, options.present_mode);
  if (!mode) return mode.error();
  target->present_mode_ = *mode;
  target->depth_format_ = choose_depth_format(physical);
  target->samples_ = clamp_samples(physical, options.samples);

  target->slots_.resize(options.frames_in_flight);
  for (Slot& slot : target->slots_) {
    Result<VkCommandBuffer> commands = context.allocate_command_buffer();
    if (!commands) return commands.error();
    slot.commands = *commands;
    // Signalled: the first begin_frame need not wait.
    Result<DeviceHandle<VkFence>> fence = context.create_fence(true);
    if (!fence) return fence.error();
    slot.done = std::move(*fence);
    VkSemaphoreCreateInfo semaphore_info =
        vk_struct<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
    VkSemaphore semaphore = VK_NULL_HANDLE;
    if (VkResult r = vkCreateSemaphore(device, &semaphore_info, nullptr, &semaphore);
        r != VK_SUCCESS) {
      return vk_error("vkCreateSemaphore", r);
    }
    slot.image_available = DeviceHandle<VkSemaphore>(device, semaphore, vkDestroySemaphore);
  }
  if (Status s = target->create_overlay_render_pass(); !s) return s.error();
  if (Status s = target->create_swapchain(); !s) return s.error();
  return target;
}

WindowTarget::~WindowTarget() {
  const VkDevice device = context_.device();
  vkDeviceWaitIdle(device);
  for (Slot& slot : slots_) {
    if (slot.commands != VK_NULL_HANDLE) {
      vkFreeCommandBuffers(device, context_.command_pool(), 1, &slot.commands);
    }
  }
  destroy_swapchain_images();
  if (swapchain_ != VK_NULL_HANDLE) vkDestroySwapchainKHR(device, swapchain_, nullptr);
  if (surface_ != VK_NULL_HANDLE) vkDestroySurfaceKHR(context_.instance(), surface_, nullptr);
}

void WindowTarget::destroy_swapchain_images() {
  overlay_framebuffers_.clear();
  image_views_.clear();
  images_.clear();
  msaa_color_ = DeviceImage{};
  scaled_color_ = DeviceImage{};
  depth_ = DeviceImage{};
}

Status WindowTarget::create_overlay_render_pass() {
  VkAttachmentDescription color{};
  color.format = color_format_;
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // draw over the main pass's picture
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;  // end_frame's barrier moves it on
  VkAttachmentReference reference{};
  reference.attachment = 0;
  reference.layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &reference;
  // The main pass's colour writes (and its resolve) before the overlay loads and blends.
  VkSubpassDependency after_main{};
  after_main.srcSubpass = VK_SUBPASS_EXTERNAL;
  after_main.dstSubpass = 0;
  after_main.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  after_main.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  after_main.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  after_main.dstAccessMask =
      VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  // The overlay's writes before end_frame's barrier (which starts at colour output again).
  VkSubpassDependency before_present{};
  before_present.srcSubpass = 0;
  before_present.dstSubpass = VK_SUBPASS_EXTERNAL;
  before_present.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  before_present.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  before_present.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  before_present.dstAccessMask = 0;
  const VkSubpassDependency dependencies[2] = {after_main, before_present};
  VkRenderPassCreateInfo info =
      vk_struct<VkRenderPassCreateInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO);
  info.attachmentCount = 1;
  info.pAttachments = &color;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 2;
  info.pDependencies = dependencies;
  VkRenderPass pass = VK_NULL_HANDLE;
  if (VkResult r = vkCreateRenderPass(context_.device(), &info, nullptr, &pass); r != VK_SUCCESS) {
    return vk_error("vkCreateRenderPass", r);
  }
  overlay_pass_ = DeviceHandle<VkRenderPass>(context_.device(), pass, vkDestroyRenderPass);
  return Status::success();
}

Status WindowTarget::wait_while_minimised() {
  for (Window::Size size = window_.framebuffer_size(); size.width == 0 || size.height == 0;
       size = window_.framebuffer_size()) {
    if (window_.should_close()) {
      return Error{"window target: the window was closed while minimised"};
    }
    window_.wait_events();
  }
  return Status::success();
}

Status WindowTarget::create_swapchain() {
  const VkPhysicalDevice physical = context_.physical_device();
  const VkDevice device = context_.device();
  VkSurfaceCapabilitiesKHR caps;
  for (;;) {
    if (Status s = wait_while_minimised(); !s) return s;
    if (VkResult r = vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface_, &caps);
        r != VK_SUCCESS) {
      return vk_error("vkGetPhysicalDeviceSurfaceCapabilitiesKHR", r);
    }
    if (caps.currentExtent.width != UINT32_MAX) {
      extent_ = caps.currentExtent;  // the surface's size is the window's
    } else {
      const Window::Size size = window_.framebuffer_size();
      extent_.width = std::clamp(size.width, caps.minImageExtent.width, caps.maxImageExtent.width);
      extent_.height =
          std::clamp(size.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    if (extent_.width > 0 && extent_.height > 0) break;
    window_.wait_events();  // minimised between the size query and the capabilities
  }

  std::uint32_t image_count = caps.minImageCount + 1;
  if (caps.maxImageCount != 0) image_count = std::min(image_count, caps.maxImageCount);
  can_copy_from_images_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;
  VkFormatProperties format_properties{};
  vkGetPhysicalDeviceFormatProperties(physical, color_format_, &format_properties);
  const VkFormatFeatureFlags blit_features = VK_FORMAT_FEATURE_BLIT_SRC_BIT |
                                             VK_FORMAT_FEATURE_BLIT_DST_BIT |
                                             VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  can_blit_ = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT) != 0 &&
              (format_properties.optimalTilingFeatures & blit_features) == blit_features;

  VkSwapchainCreateInfoKHR info =
      vk_struct<VkSwapchainCreateInfoKHR>(VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR);
  info.surface = surface_;
  info.minImageCount = image_count;
  info.imageFormat = color_format_;
  info.imageColorSpace = color_space_;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage =
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
      (can_copy_from_images_ ? VkImageUsageFlags{VK_IMAGE_USAGE_TRANSFER_SRC_BIT} : 0u) |
      (can_blit_ ? VkImageUsageFlags{VK_IMAGE_USAGE_TRANSFER_DST_BIT} : 0u);
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;  // one queue renders and presents
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = choose_composite_alpha(caps.supportedCompositeAlpha);
  info.presentMode = present_mode_;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR swapchain = VK_NULL_HANDLE;
  VkResult created = vkCreateSwapchainKHR(device, &info, nullptr, &swapchain);
  // The old swap chain is retired either way; nothing uses it (the device is idle).
  destroy_swapchain_images();
  if (swapchain_ != VK_NULL_HANDLE) vkDestroySwapchainKHR(device, swapchain_, nullptr);
  swapchain_ = VK_NULL_HANDLE;
  if (created != VK_SUCCESS) return vk_error("vkCreateSwapchainKHR", created);
  swapchain_ = swapchain;

  std::uint32_t count = 0;
  if (VkResult r = vkGetSwapchainImagesKHR(device, swapchain_, &count, nullptr); r != VK_SUCCESS) {
    return vk_error("vkGetSwapchainImagesKHR", r);
  }
  images_.resize(count);
  if (VkResult r = vkGetSwapchainImagesKHR(device, swapchain_, &count, images_.data());
      r != VK_SUCCESS) {
    return vk_error("vkGetSwapchainImagesKHR", r);
  }
  for (VkImage image : images_) {
    VkImageViewCreateInfo view_info =
        vk_struct<VkImageViewCreateInfo>(VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO);
    view_info.image = image;
    view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view_info.format = color_format_;
    view_info.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    if (VkResult r = vkCreateImageView(device, &view_info, nullptr, &view); r != VK_SUCCESS) {
      return vk_error("vkCreateImageView", r);
    }
    image_views_.emplace_back(device, view, vkDestroyImageView);
    VkFramebufferCreateInfo framebuffer_info =
        vk_struct<VkFramebufferCreateInfo>(VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO);
    framebuffer_info.renderPass = overlay_pass_.get();
    framebuffer_info.attachmentCount = 1;
    framebuffer_info.pAttachments = &view;
    framebuffer_info.width = extent_.width;
    framebuffer_info.height = extent_.height;
    framebuffer_info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    if (VkResult r = vkCreateFramebuffer(device, &framebuffer_info, nullptr, &framebuffer);
        r != VK_SUCCESS) {
      return vk_error("vkCreateFramebuffer", r);
    }
    overlay_framebuffers_.emplace_back(device, framebuffer, vkDestroyFramebuffer);
  }
  while (render_finished_.size() < images_.size()) {
    VkSemaphoreCreateInfo semaphore_info =
        vk_struct<VkSemaphoreCreateInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO);
    VkSemaphore semaphore = VK_NULL_HANDLE;
    if (VkResult r = vkCreateSemaphore(device, &semaphore_info, nullptr, &semaphore);
        r != VK_SUCCESS) {
      return vk_error("vkCreateSemaphore", r);
    }
    render_finished_.emplace_back(device, semaphore, vkDestroySemaphore);
  }

  // Depth (and the MSAA colour) live only during the main pass: transient attachments.
  const VkImageUsageFlags transient = VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
  Result<DeviceImage> depth = create_image(physical, device, depth_format_, extent_,
                                           VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | transient,
                                           VK_IMAGE_ASPECT_DEPTH_BIT, samples_);
  if (!depth) return depth.error();
  depth_ = std::move(*depth);
  if (samples_ != VK_SAMPLE_COUNT_1_BIT) {
    Result<DeviceImage> msaa = create_image(physical, device, color_format_, extent_,
                                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | transient,
                                            VK_IMAGE_ASPECT_COLOR_BIT, samples_);
    if (!msaa) return msaa.error();
    msaa_color_ = std::move(*msaa);
  }
  if (can_blit_) {
    Result<DeviceImage> scaled = create_image(
        physical, device, color_format_, extent_,
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
        VK_IMAGE_ASPECT_COLOR_BIT);
    if (!scaled) return scaled.error();
    scaled_color_ = std::move(*scaled);
  }
  return Status::success();
}

void WindowTarget::set_render_scale(float scale) {
  render_scale_ = std::isfinite(scale) ? std::clamp(scale, 0.25f, 1.0f) : 1.0f;
}

VkExtent2D WindowTarget::render_extent() const {
  const float scale = render_scale();
  if (scale >= 1.0f) return extent_;
  auto scaled = [scale](std::uint32_t pixels) {
    return std::max<std::uint32_t>(
        1, static_cast<std::uint32_t>(std::lround(static_cast<float>(pixels) * scale)));
  };
  return {scaled(extent_.width), scaled(extent_.height)};
}

Result<RecordingFrame> WindowTarget::begin_frame() {
  if (recording_) {
    return Error{"window target: begin_frame while frame " + std::to_string(next_id_) +
                 " is still being recorded"};
  }
  const VkDevice device = context_.device();
  Slot& slot = slots_[slot_index_];
  VkFence fence = slot.done.get();
  if (VkResult r = vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX); r != VK_SUCCESS) {
    return vk_error("vkWaitForFences", r);
  }

  for (int attempt = 0;; ++attempt) {
    const Window::Size size = window_.framebuffer_size();
    if (needs_recreate_ || size.width != extent_.width || size.height != extent_.height) {
      if (Status s = context_.wait_idle(); !s) return s.error();
      if (Status s = create_swapchain(); !s) return s.error();
      needs_recreate_ = false;
      ++recreate_count_;
    }
    VkResult r = vkAcquireNextImageKHR(device, swapchain_, UINT64_MAX, slot.image_available.get(),
                                       VK_NULL_HANDLE, &image_index_);
    if (r == VK_SUCCESS) break;
    if (r == VK_SUBOPTIMAL_KHR) {  // the image is acquired and usable; recreate after it
      needs_recreate_ = true;
      break;
    }
    if (r != VK_ERROR_OUT_OF_DATE_KHR || attempt + 1 == kAcquireAttempts) {
      return vk_error("vkAcquireNextImageKHR", r);
    }
    needs_recreate_ = true;  // nothing was acquired or signalled; try again with a new chain
  }

  if (VkResult r = vkResetCommandBuffer(slot.commands, 0); r != VK_SUCCESS) {
    return vk_error("vkResetCommandBuffer", r);
  }
  VkCommandBufferBeginInfo begin =
      vk_struct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  if (VkResult r = vkBeginCommandBuffer(slot.commands, &begin); r != VK_SUCCESS) {
    return vk_error("vkBeginCommandBuffer", r);
  }
  recording_ = true;
  main_pass_open_ = false;
  main_pass_done_ = false;
  overlay_open_ = false;
  overlay_done_ = false;
  return RecordingFrame{slot.commands, next_id_};
}

void WindowTarget::begin_main_pass(const ClearColor& clear) {
  if (!recording_ || main_pass_open_ || main_pass_done_) return;  // precondition: record nothing
  const VkCommandBuffer commands = slots_[slot_index_].commands;
  const VkImage image = images_[image_index_];
  scaled_pass_ = render_scale() < 1.0f;
  scaled_area_ = scaled_pass_ ? render_extent() : extent_;
  // The swap-chain image comes from the presentation engine (the acquire semaphore is waited at
  // COLOR_ATTACHMENT_OUTPUT, so the barrier chains to it there); its old contents are cleared or
  // resolved over, so its old layout does not matter.
  const VkPipelineStageFlags2 attachment_stage = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  const VkPipelineStageFlags2 depth_stages =
      VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  // Depth and MSAA colour are shared by the frames in flight: order this frame's writes after
  // the previous frame's.
  // A scaled pass draws into scaled_color_ (last read by the previous frame's blit); the
  // swap-chain image is then only written by the blit (blit_scaled_image's barriers).
  const VkImage drawn = scaled_pass_ ? scaled_color_.image.get() : image;
  record_image_barriers(
      commands,
      {image_barrier(drawn, VK_IMAGE_ASPECT_COLOR_BIT,
                     scaled_pass_ ? attachment_stage | VK_PIPELINE_STAGE_2_BLIT_BIT
                                  : attachment_stage,
                     scaled_pass_ ? VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT : VK_ACCESS_2_NONE,
                     attachment_stage, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                     VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL),
       image_barrier(depth_.image.get(), VK_IMAGE_ASPECT_DEPTH_BIT, depth_stages,
                     VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, depth_stages,
                     VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                         VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                     VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL)});
  if (msaa_color_.image) {
    record_image_barriers(
        commands,
        {image_barrier(msaa_color_.image.get(), VK_IMAGE_ASPECT_COLOR_BIT, attachment_stage,
                       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, attachment_stage,
                       VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL)});
  }

  VkRenderingAttachmentInfo color =
      vk_struct<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
  color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  color.clearValue.color = {{clear.r, clear.g, clear.b, clear.a}};
  if (msaa_color_.image) {
    color.imageView = msaa_color_.view.get();
    color.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;  // only the resolved image is kept
    color.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
    color.resolveImageView =
        scaled_pass_ ? scaled_color_.view.get() : image_views_[image_index_].get();
    color.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  } else {
    color.imageView = scaled_pass_ ? scaled_color_.view.get() : image_views_[image_index_].get();
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  }
  VkRenderingAttachmentInfo depth =
      vk_struct<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
  depth.imageView = depth_.view.get();
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo rendering = vk_struct<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
  rendering.renderArea = {{0, 0}, scaled_area_};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &color;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(commands, &rendering);

  const VkViewport viewport{
      0.0f, 0.0f, static_cast<float>(scaled_area_.width), static_cast<float>(scaled_area_.height),
      0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, scaled_area_};
  vkCmdSetViewport(commands, 0, 1, &viewport);
  vkCmdSetScissor(commands, 0, 1, &scissor);
  main_pass_open_ = true;
}

void WindowTarget::blit_scaled_image(VkCommandBuffer commands, VkExtent2D from) {
  const VkImage image = images_[image_index_];
  // The swap-chain image's barrier starts at COLOR_ATTACHMENT_OUTPUT, where the acquire
  // semaphore is waited, so the blit comes after the presentation engine let go of it.
  record_image_barriers(
      commands,
      {image_barrier(scaled_color_.image.get(), VK_IMAGE_ASPECT_COLOR_BIT,
                     VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_BLIT_BIT,
                     VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                     VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL),
       image_barrier(image, VK_IMAGE_ASPECT_COLOR_BIT,
                     VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_NONE,
                     VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                     VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL)});
  VkImageBlit region{};
  region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.srcOffsets[1] = {static_cast<std::int32_t>(from.width),
                          static_cast<std::int32_t>(from.height), 1};
  region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.dstOffsets[1] = {static_cast<std::int32_t>(extent_.width),
                          static_cast<std::int32_t>(extent_.height), 1};
  vkCmdBlitImage(commands, scaled_color_.image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_LINEAR);
  // Back to where an unscaled main pass leaves it: the overlay and finish_image go on from there.
  record_image_barriers(
      commands,
      {image_barrier(image, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_BLIT_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL)});
}

void WindowTarget::end_main_pass() {
  if (!main_pass_open_) return;
  vkCmdEndRendering(slots_[slot_index_].commands);
  if (scaled_pass_) blit_scaled_image(slots_[slot_index_].commands, scaled_area_);
  // The image stays in COLOR_ATTACHMENT_OPTIMAL: an overlay pass may follow; end_frame()
  // records its final barrier.
  main_pass_open_ = false;
  main_pass_done_ = true;
}

void WindowTarget::begin_overlay_pass() {
  if (!recording_ || overlay_open_ || overlay_done_) return;  // precondition: record nothing
  if (!main_pass_done_) begin_main_pass(ClearColor{});
  end_main_pass();
  const VkCommandBuffer commands = slots_[slot_index_].commands;
  // The render pass's external dependency orders this after the main pass's colour writes.
  VkRenderPassBeginInfo begin =
      vk_struct<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
  begin.renderPass = overlay_pass_.get();
  begin.framebuffer = overlay_framebuffers_[image_index_].get();
  begin.renderArea = {{0, 0}, extent_};
  vkCmdBeginRenderPass(commands, &begin, VK_SUBPASS_CONTENTS_INLINE);
  const VkViewport viewport{
      0.0f, 0.0f, static_cast<float>(extent_.width), static_cast<float>(extent_.height),
      0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent_};
  vkCmdSetViewport(commands, 0, 1, &viewport);
  vkCmdSetScissor(commands, 0, 1, &scissor);
  overlay_open_ = true;
}

void WindowTarget::end_overlay_pass() {
  if (!overlay_open_) return;
  vkCmdEndRenderPass(slots_[slot_index_].commands);
  overlay_open_ = false;
  overlay_done_ = true;
}

void WindowTarget::finish_image(bool capture) {
  // Colour writes (the main pass, its MSAA resolve and the overlay, all in
  // COLOR_ATTACHMENT_OUTPUT) before the present, or before the capture's copy (end_frame then
  // moves the image on to PRESENT_SRC). The semaphore signalled at the submission's end makes
  // them visible to the presentation.
  record_image_barriers(
      slots_[slot_index_].commands,
      {image_barrier(
          images_[image_index_], VK_IMAGE_ASPECT_COLOR_BIT,
          VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
          capture ? VK_PIPELINE_STAGE_2_COPY_BIT : VK_PIPELINE_STAGE_2_NONE,
          capture ? VK_ACCESS_2_TRANSFER_READ_BIT : VK_ACCESS_2_NONE,
          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
          capture ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_PRESENT_SRC_KHR)});
}

Result<std::uint64_t> WindowTarget::end_frame() {
  if (!recording_) return Error{"window target: end_frame without begin_frame"};
  if (!main_pass_done_) begin_main_pass(ClearColor{});  // present a defined image
  end_main_pass();
  end_overlay_pass();
  recording_ = false;
  const VkDevice device = context_.device();
  Slot& slot = slots_[slot_index_];
  const VkImage image = images_[image_index_];

  const bool capture = capture_requested_ && can_copy_from_images_;
  finish_image(capture);
  if (capture) {
    const VkDeviceSize size_bytes = VkDeviceSize{extent_.width} * extent_.height * 4;
    if (!capture_buffer_.buffer || capture_buffer_.size_bytes != size_bytes) {
      Result<DeviceBuffer> buffer = create_host_buffer(
          context_.physical_device(), device, size_bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
      if (!buffer) return buffer.error();
      capture_buffer_ = std::move(*buffer);
    }
    // finish_image left the image in TRANSFER_SRC, its writes visible to the copy.
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent_.width, extent_.height, 1};
    vkCmdCopyImageToBuffer(slot.commands, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           capture_buffer_.buffer.get(), 1, &region);
    VkBufferMemoryBarrier2 to_host =
        vk_struct<VkBufferMemoryBarrier2>(VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2);
    to_host.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    to_host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    to_host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    to_host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    to_host.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_host.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    to_host.buffer = capture_buffer_.buffer.get();
    to_host.size = VK_WHOLE_SIZE;
    const VkImageMemoryBarrier2 to_present =
        image_barrier(image, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                      VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
    VkDependencyInfo after_copy = vk_struct<VkDependencyInfo>(VK_STRUCTURE_TYPE_DEPENDENCY_INFO);
    after_copy.bufferMemoryBarrierCount = 1;
    after_copy.pBufferMemoryBarriers = &to_host;
    after_copy.imageMemoryBarrierCount = 1;
    after_copy.pImageMemoryBarriers = &to_present;
    vkCmdPipelineBarrier2(slot.commands, &after_copy);
    capture_extent_ = extent_;
    capture_format_ = color_format_;
  }

  if (VkResult r = vkEndCommandBuffer(slot.commands); r != VK_SUCCESS) {
    return vk_error("vkEndCommandBuffer", r);
  }
  VkFence fence = slot.done.get();
  if (VkResult r = vkResetFences(device, 1, &fence); r != VK_SUCCESS) {
    return vk_error("vkResetFences", r);
  }
  VkSemaphoreSubmitInfo wait =
      vk_struct<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
  wait.semaphore = slot.image_available.get();
  wait.stageMask = VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  VkSemaphoreSubmitInfo signal =
      vk_struct<VkSemaphoreSubmitInfo>(VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO);
  signal.semaphore = render_finished_[image_index_].get();
  signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkCommandBufferSubmitInfo command_info =
      vk_struct<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
  command_info.commandBuffer = slot.commands;
  VkSubmitInfo2 submit = vk_struct<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
  submit.waitSemaphoreInfoCount = 1;
  submit.pWaitSemaphoreInfos = &wait;
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &command_info;
  submit.signalSemaphoreInfoCount = 1;
  submit.pSignalSemaphoreInfos = &signal;
  if (VkResult r = vkQueueSubmit2(context_.graphics_queue(), 1, &submit, fence); r != VK_SUCCESS) {
    return vk_error("vkQueueSubmit2", r);
  }
  if (capture) {
    capture_requested_ = false;
    capture_pending_ = true;
  }

  const VkSemaphore render_finished = render_finished_[image_index_].get();
  VkPresentInfoKHR present = vk_struct<VkPresentInfoKHR>(VK_STRUCTURE_TYPE_PRESENT_INFO_KHR);
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &render_finished;
  present.swapchainCount = 1;
  present.pSwapchains = &swapchain_;
  present.pImageIndices = &image_index_;
  const VkResult presented = vkQueuePresentKHR(context_.graphics_queue(), &present);
  slot_index_ = (slot_index_ + 1) % static_cast<std::uint32_t>(slots_.size());
  const std::uint64_t id = next_id_++;
  if (presented == VK_SUBOPTIMAL_KHR || presented == VK_ERROR_OUT_OF_DATE_KHR) {
    needs_recreate_ = true;  // the next begin_frame recreates the swap chain
  } else if (presented != VK_SUCCESS) {
    return vk_error("vkQueuePresentKHR", presented);
  }
  return id;
}

Result<CapturedFrame> WindowTarget::take_capture() {
  if (!capture_pending_) {
    if (capture_requested_ && !can_copy_from_images_) {
      return Error{"window target: this surface's images cannot be copied (no TRANSFER_SRC)"};
    }
    return Error{"window target: no captured frame (capture_next_frame, then end a frame)"};
  }
  // A debugging aid, not a per-frame path: simply wait for everything submitted so far.
  if (Status s = context_.wait_idle(); !s) return s.error();
  if (Status s = invalidate_for_host_read(context_.device(), capture_buffer_); !s) {
    return s.error();
  }
  capture_pending_ = false;
  CapturedFrame frame;
  frame.width = capture_extent_.width;
  frame.height = capture_extent_.height;
  frame.rgba.resize(std::size_t{frame.width} * frame.height * 4);
  std::memcpy(frame.rgba.data(), capture_buffer_.mapped, frame.rgba.size());
  if (is_bgra(capture_format_)) {
    for (std::size_t i = 0; i < frame.rgba.size(); i += 4)
      std::swap(frame.rgba[i], frame.rgba[i + 2]);
  }
  return frame;
}

}  // namespace tutti::render
