#pragma once
// PNG output for rendered frames (stb_image_write; deterministic: fixed compression level, no
// timestamps). Written atomically: a reader never sees half a file.

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "core/result.hpp"

namespace tutti::render {

// `rgba`: width*height*4 bytes, tightly packed rows, top row first (what
// OffscreenTarget::read_pixels gives). An error if the size does not match or w/h is 0.
std::vector<std::uint8_t> encode_png(std::span<const std::uint8_t> rgba, std::uint32_t width,
                                     std::uint32_t height);
Status write_png(const std::filesystem::path& path, std::span<const std::uint8_t> rgba,
                 std::uint32_t width, std::uint32_t height);

}  // namespace tutti::render
