// SPDX-License-Identifier: MIT
#include <tutti/render/vulkan_context.hpp>

#include <gtest/gtest.h>

#include <algorithm>

#include <tutti/render/vk_result.hpp>
#include "render_test_support.hpp"

namespace tutti::render {
namespace {

TEST(VkResultTest, ErrorNamesTheCallAndTheResult) {
  EXPECT_EQ(vk_error("vkCreateDevice", VK_ERROR_INITIALIZATION_FAILED).message,
            "vkCreateDevice: VK_ERROR_INITIALIZATION_FAILED");
  EXPECT_EQ(to_string(static_cast<VkResult>(-123456)), "VkResult(-123456)");
  EXPECT_TRUE(vk_check("vkQueueSubmit", VK_SUCCESS));
  EXPECT_EQ(vk_check("vkQueueSubmit", VK_ERROR_DEVICE_LOST).error().message,
            "vkQueueSubmit: VK_ERROR_DEVICE_LOST");
}

class VulkanContextTest : public test::VulkanTest {};

TEST_F(VulkanContextTest, DefaultSelectionGivesAWorkingDeviceAndQueue) {
  EXPECT_TRUE(context().validation_enabled());
  EXPECT_NE(context().device(), VK_NULL_HANDLE);
  EXPECT_NE(context().graphics_queue(), VK_NULL_HANDLE);
  EXPECT_NE(context().command_pool(), VK_NULL_HANDLE);
  EXPECT_TRUE(context().device_info().usable);
  EXPECT_GE(context().device_info().api_version, VK_API_VERSION_1_3);
  std::printf("device: %s (%s)\n", context().device_info().name.c_str(),
              device_type_name(context().device_info().type));
  EXPECT_TRUE(context().wait_idle());
}

// The log really collects messages: an invalid call (a zero-sized buffer,
// VUID-VkBufferCreateInfo-size-00912) must land in it.
TEST_F(VulkanContextTest, ValidationLogCollectsErrors) {
  auto info = vk_struct<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  info.size = 0;
  info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  const VkResult result = vkCreateBuffer(context().device(), &info, nullptr, &buffer);
  if (result == VK_SUCCESS && buffer != VK_NULL_HANDLE) {
    vkDestroyBuffer(context().device(), buffer, nullptr);
  }
  const std::vector<std::string> messages = log_->messages();
  ASSERT_FALSE(messages.empty());
  EXPECT_NE(messages.front().find("VUID-VkBufferCreateInfo-size-00912"), std::string::npos)
      << messages.front();
  EXPECT_EQ(messages.front().rfind("validation error: ", 0), 0u) << messages.front();
  log_.reset();  // expected messages: the fixture must not fail the test for them
}

// Messages emitted while the context is destroyed still reach the shared log: an object left
// alive at vkDestroyDevice is reported (the fixture relies on this to catch leaked handles).
TEST(VulkanContextDestructionTest, LeakedObjectIsReportedAtDestroy) {
  VulkanContextOptions options;
  options.validation = true;
  auto context = VulkanContext::create(options);
  if (!context && test::is_no_device_error(context.error())) {
    std::printf("SKIPPED: no Vulkan device\n");
    GTEST_SKIP() << context.error().message;
  }
  ASSERT_TRUE(context) << context.error().message;
  auto log = (*context)->validation_log();
  auto info = vk_struct<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
  VkFence fence = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateFence((*context)->device(), &info, nullptr, &fence), VK_SUCCESS);
  EXPECT_EQ(log->size(), 0u);
  context = Error{"destroyed"};  // never destroys the fence
  const std::vector<std::string> messages = log->messages();
  ASSERT_FALSE(messages.empty());
  EXPECT_NE(messages.front().find("vkDestroyDevice"), std::string::npos) << messages.front();
}

TEST(VulkanDeviceSelectionTest, PicksLlvmpipeByNameSubstring) {
  auto devices = list_vulkan_devices();
  if (!devices && test::is_no_device_error(devices.error())) {
    std::printf("SKIPPED: no Vulkan device\n");
    GTEST_SKIP() << devices.error().message;
  }
  ASSERT_TRUE(devices) << devices.error().message;
  const bool has_llvmpipe = std::any_of(devices->begin(), devices->end(), [](const auto& d) {
    return d.name.find("llvmpipe") != std::string::npos;
  });
  if (!has_llvmpipe) GTEST_SKIP() << "no llvmpipe (lavapipe) device installed";

  VulkanContextOptions options;
  options.validation = true;
  options.device = "LLVMpipe";  // case-insensitive
  {
    auto context = VulkanContext::create(options);
    ASSERT_TRUE(context) << context.error().message;
    EXPECT_NE((*context)->device_info().name.find("llvmpipe"), std::string::npos);
    EXPECT_EQ((*context)->device_info().type, VK_PHYSICAL_DEVICE_TYPE_CPU);
    auto log = (*context)->validation_log();
    context = Error{"destroyed"};
    EXPECT_EQ(log->size(), 0u);
  }
  // The same device by its index.
  const auto llvmpipe = std::find_if(devices->begin(), devices->end(), [](const auto& d) {
    return d.name.find("llvmpipe") != std::string::npos;
  });
  options.device = std::to_string(llvmpipe->index);
  auto by_index = VulkanContext::create(options);
  ASSERT_TRUE(by_index) << by_index.error().message;
  EXPECT_EQ((*by_index)->device_info().name, llvmpipe->name);
}

TEST(VulkanDeviceSelectionTest, UnknownDeviceIsAClearError) {
  auto devices = list_vulkan_devices();
  if (!devices && test::is_no_device_error(devices.error())) {
    std::printf("SKIPPED: no Vulkan device\n");
    GTEST_SKIP() << devices.error().message;
  }
  ASSERT_TRUE(devices) << devices.error().message;
  VulkanContextOptions options;
  options.device = "no-such-gpu-xyz";
  auto context = VulkanContext::create(options);
  ASSERT_FALSE(context);
  EXPECT_EQ(context.error().message.rfind(
                "no Vulkan device matches \"no-such-gpu-xyz\"; available: 0: ", 0),
            0u)
      << context.error().message;
  options.device = "99";
  auto by_index = VulkanContext::create(options);
  ASSERT_FALSE(by_index);
  EXPECT_NE(by_index.error().message.find("no Vulkan device matches \"99\""), std::string::npos)
      << by_index.error().message;
}

}  // namespace
}  // namespace tutti::render
