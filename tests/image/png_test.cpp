// SPDX-License-Identifier: MIT
#include <tutti/image/png.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "testdata.hpp"

std::vector<std::uint8_t> decode_png_for_test(const std::vector<std::uint8_t>& png, int& width,
                                              int& height);

namespace tutti::image {
namespace {

TEST(PngTest, RoundTripsRgbaRowsTopFirst) {
  // 3x2, every byte distinct, alpha included.
  std::vector<std::uint8_t> rgba(3 * 2 * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>(i * 10 + 1);
  const std::filesystem::path path = tutti::test::unique_temp_path("roundtrip.png");
  Status written = write_png(path, rgba, 3, 2);
  ASSERT_TRUE(written) << written.error().message;
  std::ifstream in(path, std::ios::binary);
  const std::vector<std::uint8_t> png((std::istreambuf_iterator<char>(in)),
                                      std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  int width = 0, height = 0;
  EXPECT_EQ(decode_png_for_test(png, width, height), rgba);
  EXPECT_EQ(width, 3);
  EXPECT_EQ(height, 2);
  EXPECT_EQ(encode_png(rgba, 3, 2), png) << "encoding is deterministic";
}

TEST(PngTest, RejectsMismatchedSizes) {
  const std::vector<std::uint8_t> rgba(10);
  const Status status = write_png(tutti::test::unique_temp_path("bad.png"), rgba, 3, 2);
  ASSERT_FALSE(status);
  EXPECT_NE(status.error().message.find("cannot encode a 3x2x4 image from 10 bytes"),
            std::string::npos)
      << status.error().message;
  EXPECT_TRUE(encode_png(rgba, 0, 0).empty());
}

}  // namespace
}  // namespace tutti::image
