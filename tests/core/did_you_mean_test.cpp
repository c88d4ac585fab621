// SPDX-License-Identifier: MIT
#include <tutti/core/did_you_mean.hpp>

#include <gtest/gtest.h>

#include <array>

namespace tutti {
namespace {

constexpr std::array<std::string_view, 4> kCameraKeys{"name", "position_m", "target_m", "fov_deg"};

TEST(DidYouMean, AWordThatStartsANameIsThatName) {
  EXPECT_EQ(closest_name("fov", kCameraKeys), "fov_deg");
  EXPECT_EQ(closest_name("position", kCameraKeys), "position_m");
  EXPECT_EQ(did_you_mean("fov", kCameraKeys), " (did you mean \"fov_deg\"?)");
}

TEST(DidYouMean, ASmallEditIsCorrected) {
  EXPECT_EQ(closest_name("targt_m", kCameraKeys), "target_m");
  EXPECT_EQ(closest_name("nmae", kCameraKeys), "name");  // two letters swapped
  EXPECT_EQ(closest_name("Name", kCameraKeys), "name");
}

TEST(DidYouMean, NothingCloseIsNoSuggestion) {
  EXPECT_FALSE(closest_name("colour", kCameraKeys));
  EXPECT_FALSE(closest_name("", kCameraKeys));
  EXPECT_EQ(did_you_mean("zoom", kCameraKeys), "");
}

}  // namespace
}  // namespace tutti
