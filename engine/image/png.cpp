// SPDX-License-Identifier: MIT
// The only translation unit with stb_image_write's implementation, compiled with warnings off
// (third-party code).
#include <tutti/image/png.hpp>

#include <string>

#include <tutti/core/file_io.hpp>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb/stb_image_write.h>

namespace tutti::image {
namespace {

void append(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::vector<std::uint8_t> encode_png(std::span<const std::uint8_t> pixels, std::uint32_t width,
                                     std::uint32_t height, int channels) {
  std::vector<std::uint8_t> out;
  if (width == 0 || height == 0 || (channels != 3 && channels != 4) ||
      pixels.size() != std::size_t{width} * height * static_cast<std::size_t>(channels)) {
    return out;
  }
  stbi_write_png_compression_level = 8;
  stbi_write_png_to_func(append, &out, static_cast<int>(width), static_cast<int>(height), channels,
                         pixels.data(), static_cast<int>(width) * channels);
  return out;
}

Status write_png(const std::filesystem::path& path, std::span<const std::uint8_t> pixels,
                 std::uint32_t width, std::uint32_t height, int channels) {
  const std::vector<std::uint8_t> bytes = encode_png(pixels, width, height, channels);
  if (bytes.empty()) {
    return Error{path.string() + ": cannot encode a " + std::to_string(width) + "x" +
                 std::to_string(height) + "x" + std::to_string(channels) + " image from " +
                 std::to_string(pixels.size()) + " bytes"};
  }
  return write_file_atomically(path, std::string(bytes.begin(), bytes.end()));
}

}  // namespace tutti::image
