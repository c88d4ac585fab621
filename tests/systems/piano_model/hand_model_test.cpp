// SPDX-License-Identifier: MIT
#include <tutti/piano_model/hand_model.hpp>

#include <gtest/gtest.h>

#include <cstdlib>

#include <tutti/piano_model/content_dir.hpp>

namespace tutti::piano_model {
namespace {

using music::Hand;

TEST(HandModel, PaperRangesInMillimetresForTheMediumHand) {
  auto model = HandModel::load(default_content_dir() / "piano" / "hands.json", "", 23.5);
  ASSERT_TRUE(model.ok()) << model.error().message;
  EXPECT_EQ(model->preset(), "medium");
  const double d = 23.5;
  const double lo[5] = {-4.5, -2, -1, 0, 1};
  const double hi[5] = {1, 0.5, 1, 2, 3.5};
  for (int f = 1; f <= 5; ++f) {
    EXPECT_DOUBLE_EQ(model->range(Hand::right, f).lo_mm, lo[f - 1] * d) << f;
    EXPECT_DOUBLE_EQ(model->range(Hand::right, f).hi_mm, hi[f - 1] * d) << f;
    // Left hand mirrored.
    EXPECT_DOUBLE_EQ(model->range(Hand::left, f).lo_mm, -hi[f - 1] * d) << f;
    EXPECT_DOUBLE_EQ(model->range(Hand::left, f).hi_mm, -lo[f - 1] * d) << f;
  }
}

TEST(HandModel, PresetsScaleTheRanges) {
  const auto path = default_content_dir() / "piano" / "hands.json";
  auto small = HandModel::load(path, "small", 23.5);
  auto large = HandModel::load(path, "large", 23.5);
  ASSERT_TRUE(small.ok() && large.ok());
  EXPECT_LT(small->range(Hand::right, 5).hi_mm, large->range(Hand::right, 5).hi_mm);
  auto unknown = HandModel::load(path, "giant", 23.5);
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.error().message.find("hands.json: /presets: no preset 'giant'"),
            std::string::npos)
      << unknown.error().message;
}

TEST(ContentDir, EnvironmentOverridesTheBuiltInFolder) {
  ::setenv("TUTTI_CONTENT_DIR", "/tmp/elsewhere", 1);
  EXPECT_EQ(default_content_dir(), std::filesystem::path("/tmp/elsewhere"));
  ::unsetenv("TUTTI_CONTENT_DIR");
  EXPECT_TRUE(std::filesystem::exists(default_content_dir() / "piano" / "keyboard.json"));
}

}  // namespace
}  // namespace tutti::piano_model
