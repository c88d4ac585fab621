// SPDX-License-Identifier: MIT
#pragma once
// `--size WxH` as `tutti render` (an output, even sizes from 16x16) and `tutti play` (a window,
// from 320x240) take it: one parser, one message, "--size "T": expected WxH, ..., from AxB to
// 7680x4320".

#include <string>

#include <tutti/core/result.hpp>

namespace tutti::cli {

struct Size {
  int width = 0;
  int height = 0;
};

Result<Size> parse_size_option(const std::string& text, int min_width, int min_height,
                               bool even);

}  // namespace tutti::cli
