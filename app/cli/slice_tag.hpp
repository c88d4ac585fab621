// SPDX-License-Identifier: MIT
#pragma once
// What a rendered .mp4 says about itself, so `tutti concat` can check that slices rendered on
// different machines fit together: "tutti-slice frames=A:B fps=N tempo=T size=WxH lossless=0|1",
// in the file's "comment" tag.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace tutti::cli {

struct SliceTag {
  std::int64_t first = 0;  // frames [first, end) of the scene
  std::int64_t end = 0;
  int fps = 30;
  double tempo = 1.0;
  int width = 0;
  int height = 0;
  bool lossless = false;
  friend bool operator==(const SliceTag&, const SliceTag&) = default;
};

std::string format_slice_tag(const SliceTag& tag);
// nullopt: not a tutti slice tag (or a malformed one).
std::optional<SliceTag> parse_slice_tag(std::string_view text);

}  // namespace tutti::cli
