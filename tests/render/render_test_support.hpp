// SPDX-License-Identifier: MIT
#pragma once
// A validated Vulkan context per test. No Vulkan device at all → the test prints
// "SKIPPED: no Vulkan device" and is skipped (CI installs lavapipe, so there it runs). Any
// validation message — also one emitted while the context is destroyed — fails the test.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <tutti/render/vulkan_context.hpp>

namespace tutti::render::test {

inline bool is_no_device_error(const Error& error) {
  return error.message.rfind("no Vulkan device found", 0) == 0;
}

class VulkanTest : public ::testing::Test {
 protected:
  void SetUp() override {
    VulkanContextOptions options;
    options.validation = true;
    options.synchronization_validation = true;
    auto context = VulkanContext::create(options);
    if (!context && is_no_device_error(context.error())) {
      std::printf("SKIPPED: no Vulkan device\n");
      GTEST_SKIP() << context.error().message;
    }
    ASSERT_TRUE(context) << context.error().message;
    context_ = std::move(*context);
    log_ = context_->validation_log();
  }

  void TearDown() override {
    context_.reset();
    if (log_ == nullptr) return;
    const std::vector<std::string> messages = log_->messages();
    for (const std::string& message : messages) std::printf("%s\n", message.c_str());
    EXPECT_TRUE(messages.empty()) << messages.size() << " validation message(s), printed above";
  }

  VulkanContext& context() { return *context_; }

  std::unique_ptr<VulkanContext> context_;
  std::shared_ptr<const ValidationLog> log_;
};

// Linear-light value in [0, 1] → 8-bit sRGB code, as an R8G8B8A8_SRGB attachment stores it.
inline int srgb_byte(float linear) {
  const double c = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
  return static_cast<int>(std::lround(c * 255.0));
}

struct Rgb {
  int r, g, b;
};

inline Rgb srgb(float r, float g, float b) { return {srgb_byte(r), srgb_byte(g), srgb_byte(b)}; }

// Pixel (x, y) of tightly packed RGBA8 rows, as "r g b a" for failure messages.
inline std::string pixel_string(const std::vector<std::uint8_t>& rgba, std::uint32_t width,
                                std::uint32_t x, std::uint32_t y) {
  const std::size_t i = (std::size_t{y} * width + x) * 4;
  return std::to_string(rgba[i]) + " " + std::to_string(rgba[i + 1]) + " " +
         std::to_string(rgba[i + 2]) + " " + std::to_string(rgba[i + 3]);
}

// Whether pixel (x, y) is `expected` within ±tolerance per channel and fully opaque.
inline ::testing::AssertionResult pixel_near(const std::vector<std::uint8_t>& rgba,
                                             std::uint32_t width, std::uint32_t x, std::uint32_t y,
                                             Rgb expected, int tolerance = 2) {
  const std::size_t i = (std::size_t{y} * width + x) * 4;
  const int got[4] = {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
  const int want[4] = {expected.r, expected.g, expected.b, 255};
  for (int c = 0; c < 4; ++c) {
    if (std::abs(got[c] - want[c]) > tolerance) {
      return ::testing::AssertionFailure()
             << "pixel (" << x << ", " << y << ") is " << pixel_string(rgba, width, x, y)
             << ", expected " << want[0] << " " << want[1] << " " << want[2] << " 255 (±"
             << tolerance << ")";
    }
  }
  return ::testing::AssertionSuccess();
}

}  // namespace tutti::render::test
