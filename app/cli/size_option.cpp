// SPDX-License-Identifier: MIT
#include <tutti/cli/size_option.hpp>

#include <cstdio>

namespace tutti::cli {

Result<Size> parse_size_option(const std::string& text, int min_width, int min_height,
                               bool even) {
  Size size;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &size.width, &size.height, &extra) != 2 ||
      size.width < min_width || size.height < min_height || size.width > 7680 ||
      size.height > 4320 || (even && (size.width % 2 != 0 || size.height % 2 != 0))) {
    return Error{"--size \"" + text + "\": expected WxH, " + (even ? "even, " : "") + "from " +
                 std::to_string(min_width) + "x" + std::to_string(min_height) +
                 " to 7680x4320"};
  }
  return size;
}

}  // namespace tutti::cli
