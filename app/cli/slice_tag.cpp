// SPDX-License-Identifier: MIT
#include <tutti/cli/slice_tag.hpp>

#include <cstdio>
#include <cstring>

namespace tutti::cli {

std::string format_slice_tag(const SliceTag& tag) {
  char text[200];
  std::snprintf(text, sizeof text,
                "tutti-slice frames=%lld:%lld fps=%d tempo=%.17g size=%dx%d lossless=%d",
                static_cast<long long>(tag.first), static_cast<long long>(tag.end), tag.fps,
                tag.tempo, tag.width, tag.height, tag.lossless ? 1 : 0);
  return text;
}

std::optional<SliceTag> parse_slice_tag(std::string_view text) {
  // Trailing whitespace (ffprobe prints a newline) is not part of the tag.
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) {
    text.remove_suffix(1);
  }
  const std::string copy(text);
  long long first = 0, end = 0;
  int fps = 0, width = 0, height = 0, lossless = 0, used = 0;
  double tempo = 0.0;
  if (std::sscanf(copy.c_str(),
                  "tutti-slice frames=%lld:%lld fps=%d tempo=%lf size=%dx%d lossless=%d%n", &first,
                  &end, &fps, &tempo, &width, &height, &lossless, &used) != 7 ||
      static_cast<std::size_t>(used) != copy.size()) {
    return std::nullopt;
  }
  if (first < 0 || end <= first || fps < 1 || !(tempo > 0.0) || width < 1 || height < 1 ||
      (lossless != 0 && lossless != 1)) {
    return std::nullopt;
  }
  return SliceTag{first, end, fps, tempo, width, height, lossless == 1};
}

}  // namespace tutti::cli
