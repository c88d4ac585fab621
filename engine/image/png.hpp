// SPDX-License-Identifier: MIT
#pragma once
// PNG output for rendered frames and plots (stb_image_write; deterministic: fixed compression
// level, no timestamps). Written atomically: a reader never sees half a file.

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include <tutti/core/result.hpp>

namespace tutti::image {

// `pixels`: width*height*channels bytes (channels 3 = RGB, 4 = RGBA), tightly packed rows, top
// row first (what render::OffscreenTarget::read_pixels gives with 4). encode_png is empty and
// write_png an error if the size does not match, w/h is 0 or channels is not 3 or 4.
std::vector<std::uint8_t> encode_png(std::span<const std::uint8_t> pixels, std::uint32_t width,
                                     std::uint32_t height, int channels = 4);
Status write_png(const std::filesystem::path& path, std::span<const std::uint8_t> pixels,
                 std::uint32_t width, std::uint32_t height, int channels = 4);

}  // namespace tutti::image
