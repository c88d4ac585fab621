// SPDX-License-Identifier: MIT
// The tag a rendered .mp4 carries so `tutti concat` can check its slices fit together.
#include <tutti/cli/slice_tag.hpp>

#include <gtest/gtest.h>

namespace tutti::cli {
namespace {

TEST(SliceTag, RoundTrips) {
  const SliceTag tag{120, 240, 30, 0.5, 1280, 720, true};
  const std::string text = format_slice_tag(tag);
  EXPECT_EQ(text, "tutti-slice frames=120:240 fps=30 tempo=0.5 size=1280x720 lossless=1");
  EXPECT_EQ(parse_slice_tag(text), tag);
  EXPECT_EQ(parse_slice_tag(text + "\n"), tag);  // as ffprobe prints it
}

TEST(SliceTag, AnythingElseIsNotATag) {
  for (const char* text :
       {"", "Lavf59.27.100", "tutti-slice frames=5:5 fps=30 tempo=1 size=16x16 lossless=0",
        "tutti-slice frames=-1:5 fps=30 tempo=1 size=16x16 lossless=0",
        "tutti-slice frames=0:5 fps=0 tempo=1 size=16x16 lossless=0",
        "tutti-slice frames=0:5 fps=30 tempo=1 size=16x16 lossless=2",
        "tutti-slice frames=0:5 fps=30 tempo=1 size=16x16 lossless=0 extra",
        "tutti-slice frames=0:5 fps=30 tempo=nan size=16x16 lossless=0"}) {
    EXPECT_FALSE(parse_slice_tag(text).has_value()) << text;
  }
}

}  // namespace
}  // namespace tutti::cli
